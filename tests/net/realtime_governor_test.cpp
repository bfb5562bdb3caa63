// The real-time governor's rule (app/realtime_governor.h), on figures per window: behind real time
// the periphery gain grows in proportion, never past its ceiling; with time to spare it returns to
// the configured one; in between it holds.
#include <gtest/gtest.h>

#include <limits>

#include "app/realtime_governor.h"

namespace {

TEST(RealtimeGovernor, BehindRealTimeTheGainGrowsWithTheShortfall) {
  app::RealtimeGovernor slightly(1.0, 4.0), far(1.0, 4.0);
  const double a = slightly.update(0.45, 0.5, 0.5);  // 0.9 of real time
  const double b = far.update(0.2, 0.5, 0.5);        // 0.4 of real time
  EXPECT_GT(a, 1.0);
  EXPECT_GT(b, a);
  EXPECT_DOUBLE_EQ(slightly.realtimeRatio(), 0.9);
  EXPECT_LE(b, 2.0) << "one window at most doubles the gain";
}

TEST(RealtimeGovernor, TheGainStopsAtItsCeiling) {
  app::RealtimeGovernor g(1.0, 4.0);
  EXPECT_FALSE(g.atCeiling());
  for (int w = 0; w < 20; ++w) g.update(0.1, 0.5, 0.5);
  EXPECT_DOUBLE_EQ(g.gain(), 4.0);
  EXPECT_DOUBLE_EQ(g.maxGain(), 4.0);
  EXPECT_TRUE(g.atCeiling());
  g.reset(1.0);
  EXPECT_FALSE(g.atCeiling());
}

TEST(RealtimeGovernor, WithTimeToSpareItReturnsToTheConfiguredGain) {
  app::RealtimeGovernor g(1.5, 4.0);
  for (int w = 0; w < 5; ++w) g.update(0.3, 0.5, 0.5);
  ASSERT_GT(g.gain(), 1.5);
  for (int w = 0; w < 100; ++w) g.update(0.5, 0.5, 0.1);  // real time, the steps 20 % busy
  EXPECT_DOUBLE_EQ(g.gain(), 1.5);
}

TEST(RealtimeGovernor, InRealTimeAndBusyItHolds) {
  app::RealtimeGovernor g(1.0, 4.0);
  g.update(0.3, 0.5, 0.5);
  const double held = g.gain();
  g.update(0.5, 0.5, 0.45);  // real time, the steps 90 % busy
  EXPECT_DOUBLE_EQ(g.gain(), held);
  g.update(0.48, 0.5, 0.1);  // 0.96 of real time: within the dead band, whatever the spare time
  EXPECT_DOUBLE_EQ(g.gain(), held);
}

TEST(RealtimeGovernor, NonsenseFiguresChangeNothing) {
  app::RealtimeGovernor g(1.0, 4.0);
  g.update(0.3, 0.5, 0.5);
  const double held = g.gain();
  g.update(0.5, 0.0, 0.1);
  g.update(std::numeric_limits<double>::quiet_NaN(), 0.5, 0.1);
  EXPECT_DOUBLE_EQ(g.gain(), held);
}

TEST(RealtimeGovernor, AResetBringsBackTheConfiguredGain) {
  app::RealtimeGovernor g(1.0, 4.0);
  g.update(0.1, 0.5, 0.5);
  g.reset(2.0);
  EXPECT_DOUBLE_EQ(g.gain(), 2.0);
  EXPECT_DOUBLE_EQ(g.realtimeRatio(), 0.0);
}

}  // namespace
