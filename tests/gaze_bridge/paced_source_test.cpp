#include "paced_source.h"

#include <gtest/gtest.h>

using gaze_bridge::ReplaySource;
using gaze_bridge::SyntheticSource;
using gaze_bridge::TrackerSample;

namespace {

gaze::GazeRecording threeSamples() {
  gaze::GazeRecording r;
  r.samples = {{10.0, 0.1, 0.2, true}, {10.01, 0.3, 0.4, false}, {10.02, 0.5, 0.6, true}};
  return r;
}

std::vector<TrackerSample> collect(gaze_bridge::GazeSource& source, std::size_t count) {
  std::vector<TrackerSample> out;
  for (int turns = 0; out.size() < count && turns < 10000 && !source.finished(); ++turns) source.poll(out, 50);
  return out;
}

}  // namespace

TEST(ReplaySource, ReplaysInOrderAndLoopsWithIncreasingTrackerTime) {
  ReplaySource source(threeSamples(), 20.0, true);  // 20x: 10 ms samples every 0.5 ms
  const auto out = collect(source, 7);
  ASSERT_GE(out.size(), 7u);
  EXPECT_EQ(out[0].x, 0.1);
  EXPECT_EQ(out[0].y, 0.2);
  EXPECT_TRUE(out[0].valid);
  EXPECT_FALSE(out[1].valid);
  EXPECT_EQ(out[1].confidence, 0.0f);
  EXPECT_EQ(out[2].x, 0.5);
  // Second loop: same points, tracker time one period (duration 0.02 + one interval 0.01) later.
  EXPECT_EQ(out[3].x, 0.1);
  EXPECT_NEAR(out[3].tracker_time_s, 10.03, 1e-12);
  EXPECT_NEAR(out[6].tracker_time_s, 10.06, 1e-12);
  for (std::size_t i = 1; i < out.size(); ++i) {
    EXPECT_GT(out[i].tracker_time_s, out[i - 1].tracker_time_s);
    EXPECT_GE(out[i].arrival_ns, out[i - 1].arrival_ns);
  }
  EXPECT_FALSE(source.finished());
}

TEST(ReplaySource, OnceStopsAtTheEnd) {
  ReplaySource source(threeSamples(), 50.0, false);
  const auto out = collect(source, 100);
  EXPECT_EQ(out.size(), 3u);
  EXPECT_TRUE(source.finished());
}

TEST(ReplaySource, RejectsBadSpeedAndEmptyRecording) {
  EXPECT_THROW(ReplaySource(threeSamples(), 0.0, true), std::invalid_argument);
  EXPECT_THROW(ReplaySource(threeSamples(), -1.0, true), std::invalid_argument);
  EXPECT_THROW(ReplaySource(gaze::GazeRecording{}, 1.0, true), std::invalid_argument);
  EXPECT_THROW(ReplaySource("/nonexistent/gaze.csv", 1.0, true), gaze::GazeFormatError);
}

TEST(SyntheticSource, EmitsTheModelsSamples) {
  gaze::FixationModelParams params;
  params.rate_hz = 1000;
  params.seed = 9;
  SyntheticSource source(params);
  const auto out = collect(source, 50);
  ASSERT_GE(out.size(), 50u);
  gaze::FixationSaccadeModel model(params);
  for (std::size_t i = 0; i < 50; ++i) {
    const gaze::GazePoint expected = model.next();
    EXPECT_EQ(out[i].x, expected.x);
    EXPECT_EQ(out[i].y, expected.y);
    EXPECT_EQ(out[i].tracker_time_s, expected.time_s);
  }
  EXPECT_EQ(source.id(), "synthetic");
  EXPECT_TRUE(source.connected());
}
