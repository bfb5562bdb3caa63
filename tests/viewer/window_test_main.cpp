// Window tests need an X display: DisplayEnvironment starts Xvfb when DISPLAY is unset.
#include <gtest/gtest.h>

#include "viewer_process.h"

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ::testing::AddGlobalTestEnvironment(new viewer_test::DisplayEnvironment);
  return RUN_ALL_TESTS();
}
