#include "gaze_processor.h"

#include <gtest/gtest.h>

#include <cmath>

using gaze_bridge::GazeProcessor;
using gaze_bridge::ProcessedSample;
using gaze_bridge::ProcessorParams;
using gaze_bridge::TrackerSample;

namespace {

constexpr std::int64_t kMs = 1'000'000;

TrackerSample sample(double t, double x, double y, bool valid = true, float confidence = 1.0f) {
  TrackerSample s;
  s.tracker_time_s = t;
  s.x = x;
  s.y = y;
  s.valid = valid;
  s.confidence = confidence;
  s.arrival_ns = static_cast<std::int64_t>(t * 1e9) + 1000 * kMs;  // bridge clock: tracker time + 1 s
  return s;
}

ProcessorParams unfiltered() {
  ProcessorParams p;
  p.filter = false;
  return p;
}

}  // namespace

TEST(GazeProcessor, DropsInvalidLowConfidenceAndOffScreenSamples) {
  GazeProcessor processor(unfiltered(), 1000 * kMs);
  ProcessedSample out;
  EXPECT_FALSE(processor.accept(sample(0.00, 0.5, 0.5, false), out));
  EXPECT_FALSE(processor.accept(sample(0.01, 0.5, 0.5, true, 0.59f), out));
  EXPECT_FALSE(processor.accept(sample(0.02, 1.2, 0.5), out));
  EXPECT_FALSE(processor.accept(sample(0.03, 0.5, std::nan("")), out));
  ASSERT_TRUE(processor.accept(sample(0.04, 0.25, 0.75, true, 0.6f), out));
  EXPECT_EQ(out.x, 0.25);
  EXPECT_EQ(out.y, 0.75);
  EXPECT_TRUE(out.valid);
  EXPECT_FALSE(out.lost);
  EXPECT_FLOAT_EQ(out.confidence, 0.6f);
  EXPECT_EQ(out.tracker_time_s, 0.04);
  const auto& c = processor.counters();
  EXPECT_EQ(c.received, 5u);
  EXPECT_EQ(c.accepted, 1u);
  EXPECT_EQ(c.dropped_invalid, 1u);
  EXPECT_EQ(c.dropped_confidence, 1u);
  EXPECT_EQ(c.dropped_bad, 2u);
}

TEST(GazeProcessor, ConfidenceThresholdIsConfigurable) {
  ProcessorParams p = unfiltered();
  p.min_confidence = 0.9;
  GazeProcessor processor(p, 0);
  ProcessedSample out;
  EXPECT_FALSE(processor.accept(sample(0.0, 0.5, 0.5, true, 0.8f), out));
  EXPECT_TRUE(processor.accept(sample(0.01, 0.5, 0.5, true, 0.95f), out));
}

TEST(GazeProcessor, BridgesShortGapsAndReportsLongOnesOnce) {
  ProcessorParams p = unfiltered();
  p.max_gap_s = 0.2;
  p.lost_repeat_s = 1.0;
  GazeProcessor processor(p, 1000 * kMs);
  ProcessedSample out;
  ASSERT_TRUE(processor.accept(sample(0.0, 0.3, 0.3), out));  // arrives at bridge time 1000 ms
  // A 150 ms blink: invalid samples, nothing sent, no lost notice.
  for (int i = 1; i <= 15; ++i) EXPECT_FALSE(processor.accept(sample(0.01 * i, 0.3, 0.3, false), out));
  EXPECT_FALSE(processor.checkLost(1150 * kMs, out));
  EXPECT_FALSE(processor.checkLost(1200 * kMs, out));  // exactly max_gap: still bridged
  ASSERT_TRUE(processor.accept(sample(0.16, 0.31, 0.3), out));
  EXPECT_FALSE(processor.lost());
  // Now silence: lost once after 200 ms, then every second.
  EXPECT_FALSE(processor.checkLost(1300 * kMs, out));
  ASSERT_TRUE(processor.checkLost(1361 * kMs, out));
  EXPECT_TRUE(out.lost);
  EXPECT_FALSE(out.valid);
  EXPECT_EQ(out.x, 0.31);  // last point kept for recordings
  EXPECT_TRUE(processor.lost());
  EXPECT_FALSE(processor.checkLost(1400 * kMs, out));
  EXPECT_FALSE(processor.checkLost(2300 * kMs, out));
  EXPECT_TRUE(processor.checkLost(2361 * kMs, out));
  EXPECT_EQ(processor.counters().lost_sent, 2u);
  // Gaze comes back: sent at once, lost cleared.
  TrackerSample back = sample(2.0, 0.6, 0.6);
  back.arrival_ns = 2400 * kMs;
  ASSERT_TRUE(processor.accept(back, out));
  EXPECT_FALSE(out.lost);
  EXPECT_FALSE(processor.lost());
}

TEST(GazeProcessor, TrackerThatNeverDeliversIsReportedLost) {
  GazeProcessor processor(unfiltered(), 0);
  ProcessedSample out;
  EXPECT_FALSE(processor.checkLost(100 * kMs, out));
  EXPECT_TRUE(processor.checkLost(201 * kMs, out));
  EXPECT_TRUE(out.lost);
  EXPECT_EQ(processor.nextDeadlineNs(), 1201 * kMs);
}

TEST(GazeProcessor, FilterSmoothsWithinFixationAndRestartsAfterLostGaze) {
  ProcessorParams p;  // filter on, defaults
  GazeProcessor processor(p, 1000 * kMs);
  ProcessedSample out;
  ASSERT_TRUE(processor.accept(sample(0.000, 0.30, 0.30), out));
  EXPECT_EQ(out.x, 0.30);  // first sample passes through
  ASSERT_TRUE(processor.accept(sample(0.005, 0.31, 0.30), out));
  EXPECT_GT(out.x, 0.30);
  EXPECT_LT(out.x, 0.305);  // smoothed towards the history
  ASSERT_TRUE(processor.checkLost(2000 * kMs, out));
  // After the lost period the filter starts afresh: the new point is not dragged towards 0.3.
  TrackerSample back = sample(1.5, 0.8, 0.8);
  back.arrival_ns = 2100 * kMs;
  ASSERT_TRUE(processor.accept(back, out));
  EXPECT_EQ(out.x, 0.8);
  EXPECT_EQ(out.y, 0.8);
}

TEST(GazeProcessor, TrackerClockGoingBackwardsRestartsFilter) {
  GazeProcessor processor(ProcessorParams{}, 1000 * kMs);
  ProcessedSample out;
  ASSERT_TRUE(processor.accept(sample(5.000, 0.2, 0.2), out));
  ASSERT_TRUE(processor.accept(sample(5.005, 0.2, 0.2), out));
  TrackerSample restarted = sample(0.0, 0.9, 0.9);
  restarted.arrival_ns = 1000 * kMs + 5010 * kMs;
  ASSERT_TRUE(processor.accept(restarted, out));
  EXPECT_EQ(out.x, 0.9);  // no smoothing across the restart
}

TEST(GazeProcessor, IvtFlagsFixationsButNotSaccades) {
  ProcessorParams p = unfiltered();
  p.ivt = true;
  p.ivt_threshold = 0.6;
  p.screen_aspect = 2.0;
  GazeProcessor processor(p, 1000 * kMs);
  ProcessedSample out;
  ASSERT_TRUE(processor.accept(sample(0.00, 0.5, 0.5), out));
  EXPECT_FALSE(out.fixation);                                    // no speed yet
  ASSERT_TRUE(processor.accept(sample(0.01, 0.502, 0.5), out));  // 0.2 widths/s
  EXPECT_TRUE(out.fixation);
  ASSERT_TRUE(processor.accept(sample(0.02, 0.512, 0.5), out));  // 1.0 widths/s
  EXPECT_FALSE(out.fixation);
  // Vertical: 0.01 heights in 10 ms = 1 height/s = 0.5 widths/s with aspect 2 -> fixation.
  ASSERT_TRUE(processor.accept(sample(0.03, 0.512, 0.51), out));
  EXPECT_TRUE(out.fixation);
  p.ivt = false;
  GazeProcessor no_ivt(p, 1000 * kMs);
  ASSERT_TRUE(no_ivt.accept(sample(0.00, 0.5, 0.5), out));
  ASSERT_TRUE(no_ivt.accept(sample(0.01, 0.5, 0.5), out));
  EXPECT_FALSE(out.fixation);
}

TEST(GazeProcessor, RejectsBadParameters) {
  ProcessorParams p;
  p.min_confidence = 1.5;
  EXPECT_THROW(GazeProcessor(p, 0), std::invalid_argument);
  p = ProcessorParams{};
  p.max_gap_s = 0;
  EXPECT_THROW(GazeProcessor(p, 0), std::invalid_argument);
  p = ProcessorParams{};
  p.one_euro.beta = -1;
  EXPECT_THROW(GazeProcessor(p, 0), std::invalid_argument);
}
