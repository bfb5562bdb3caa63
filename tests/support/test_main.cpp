// The main() of the test programs: the OpenMP wait policy the project's programs choose for
// themselves (process/omp_wait.h), then GoogleTest.
//
// ctest runs two test programs at once on a machine that may have two cores; with libgomp's
// default wait, a thread spinning at a barrier keeps its core while its partner in the same
// process waits for one, and a solver with many barriers a step (pbf's Jacobi iterations) then
// runs so slowly that it passes a test's hang timeout.
#include <gtest/gtest.h>

#include "process/omp_wait.h"

int main(int argc, char** argv) {
  process::applyDefaultOmpWaitPolicy(argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
