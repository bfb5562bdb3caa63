// The publish clock's rules on made-up times (no clock is read): the regular cadence, an early frame
// for a new gaze sample, the cap of two frames per period, and a rate change that applies at once.
#include "app/publish_pacer.h"

#include <gtest/gtest.h>

namespace {

using app::PublishPacer;
using std::chrono::milliseconds;
using Time = PublishPacer::Clock::time_point;

const Time t0 = Time() + std::chrono::hours(1);

TEST(PublishPacer, KeepsTheCadenceOfItsRate) {
  PublishPacer pacer(10.0, t0);  // a frame every 100 ms
  EXPECT_TRUE(pacer.due(t0));
  pacer.published(t0 + milliseconds(3));  // published a little late: the cadence stays on t0
  EXPECT_EQ(pacer.nextDue(), t0 + milliseconds(100));
  EXPECT_FALSE(pacer.due(t0 + milliseconds(99)));
  pacer.published(t0 + milliseconds(100));
  EXPECT_EQ(pacer.nextDue(), t0 + milliseconds(200));
  // A loop a whole period behind starts a new cadence instead of bursting.
  pacer.published(t0 + milliseconds(450));
  EXPECT_EQ(pacer.nextDue(), t0 + milliseconds(550));
}

TEST(PublishPacer, ANewGazeSampleIsPublishedAtOnce) {
  PublishPacer pacer(10.0, t0);
  pacer.published(t0);
  pacer.freshSample();
  EXPECT_TRUE(pacer.due(t0 + milliseconds(5))) << "one frame in the period so far: a second may follow";
  pacer.published(t0 + milliseconds(5));
  // The early frame restarts the regular clock.
  EXPECT_EQ(pacer.nextDue(), t0 + milliseconds(105));
  EXPECT_FALSE(pacer.due(t0 + milliseconds(104)));
}

TEST(PublishPacer, NeverMoreThanTwoFramesPerPeriod) {
  PublishPacer pacer(10.0, t0);
  pacer.published(t0);
  pacer.freshSample();
  pacer.published(t0 + milliseconds(5));
  pacer.freshSample();  // another new sample at once: the frame before the last was at t0
  EXPECT_FALSE(pacer.due(t0 + milliseconds(50)));
  EXPECT_EQ(pacer.nextDue(), t0 + milliseconds(100));
  pacer.published(t0 + milliseconds(100));
  // Fresh samples at every chance: frames at 0, 5, 100, 105, 200, ... never three in 100 ms.
  pacer.freshSample();
  EXPECT_EQ(pacer.nextDue(), t0 + milliseconds(105));
}

TEST(PublishPacer, ARateChangeAppliesFromTheNextFrame) {
  PublishPacer pacer(60.0, t0);
  pacer.published(t0);
  pacer.setRate(1e-3);  // a frame every 1000 s
  EXPECT_EQ(pacer.nextDue(), t0 + std::chrono::seconds(1000));
  pacer.setRate(60.0);  // back: the old far-off deadline is not kept
  EXPECT_LE(pacer.nextDue(), t0 + milliseconds(17));
  EXPECT_DOUBLE_EQ(pacer.rate(), 60.0);
}

TEST(PublishPacer, TheSlowestRateIsASaneDuration) {
  PublishPacer pacer(1e-3, t0);
  pacer.published(t0);
  EXPECT_EQ(pacer.nextDue(), t0 + std::chrono::seconds(1000));
  EXPECT_GT(pacer.nextDue(), t0) << "1 / hz overflowed";
}

}  // namespace
