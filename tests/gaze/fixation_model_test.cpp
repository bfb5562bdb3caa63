#include "gaze/fixation_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

#include "temp_file.h"

using gaze::FixationModelParams;
using gaze::FixationSaccadeModel;
using gaze::GazePoint;

namespace {

struct Labelled {
  GazePoint point;
  FixationSaccadeModel::Phase phase;
  std::uint64_t fixation;
};

std::vector<Labelled> runModel(const FixationModelParams& params, int count) {
  FixationSaccadeModel model(params);
  std::vector<Labelled> out;
  for (int i = 0; i < count; ++i) {
    const GazePoint p = model.next();
    out.push_back({p, model.phase(), model.fixationIndex()});
  }
  return out;
}

}  // namespace

TEST(FixationModel, SameSeedGivesSameSamples) {
  FixationModelParams params;
  params.seed = 42;
  params.blink_probability = 0.3;
  const auto a = gaze::synthesizeRecording(params, 20.0);
  const auto b = gaze::synthesizeRecording(params, 20.0);
  ASSERT_EQ(a.samples.size(), b.samples.size());
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    ASSERT_EQ(a.samples[i].time_s, b.samples[i].time_s);
    ASSERT_EQ(a.samples[i].x, b.samples[i].x);
    ASSERT_EQ(a.samples[i].y, b.samples[i].y);
    ASSERT_EQ(a.samples[i].valid, b.samples[i].valid);
  }
}

TEST(FixationModel, DifferentSeedGivesDifferentSamples) {
  FixationModelParams params;
  params.seed = 1;
  const auto a = gaze::synthesizeRecording(params, 2.0);
  params.seed = 2;
  const auto b = gaze::synthesizeRecording(params, 2.0);
  ASSERT_EQ(a.samples.size(), b.samples.size());
  int differing = 0;
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    if (a.samples[i].x != b.samples[i].x || a.samples[i].y != b.samples[i].y) ++differing;
  }
  EXPECT_EQ(differing, static_cast<int>(a.samples.size()));
}

TEST(FixationModel, FirstSamplesArePinnedAcrossPlatforms) {
  // The first draw of std::mt19937_64 seeded with 1 is fixed by the standard (its 10000th output
  // for the default seed is required to be 9981545732273789042). Our uniform transform takes its top
  // 53 bits, so the first target x is fully determined; pin it so a change of transform is noticed.
  std::mt19937_64 engine(1);
  const double u0 = static_cast<double>(engine() >> 11) * 0x1.0p-53;
  FixationModelParams params;
  params.jitter = 0.0;
  FixationSaccadeModel model(params);
  const GazePoint first = model.next();
  EXPECT_EQ(first.x, params.region_x0 + (params.region_x1 - params.region_x0) * u0);
  EXPECT_EQ(first.time_s, 0.0);
  EXPECT_TRUE(first.valid);
}

TEST(FixationModel, SamplesComeAtTheRate) {
  for (double rate : {60.0, 120.0, 200.0}) {
    FixationModelParams params;
    params.rate_hz = rate;
    const auto recording = gaze::synthesizeRecording(params, 3.0);
    ASSERT_EQ(recording.samples.size(), static_cast<std::size_t>(3.0 * rate) + 1) << rate;
    EXPECT_DOUBLE_EQ(recording.duration(), 3.0);
    for (std::size_t i = 1; i < recording.samples.size(); ++i) {
      ASSERT_NEAR(recording.samples[i].time_s - recording.samples[i - 1].time_s, 1.0 / rate, 1e-12);
    }
  }
}

TEST(FixationModel, FixationDurationsStayWithinBounds) {
  FixationModelParams params;
  params.seed = 7;
  const auto samples = runModel(params, 120 * 60);
  std::map<std::uint64_t, int> fixation_samples;
  std::map<std::uint64_t, int> saccade_samples;
  for (const Labelled& s : samples) {
    (s.phase == FixationSaccadeModel::Phase::kFixation ? fixation_samples : saccade_samples)[s.fixation]++;
  }
  ASSERT_GT(fixation_samples.size(), 100u);            // a minute of 0.2-0.4 s fixations: about 180
  const auto last = fixation_samples.rbegin()->first;  // may be cut off by the end of the run
  double min_s = 1e9, max_s = 0.0;
  for (const auto& [index, count] : fixation_samples) {
    if (index == last) continue;
    const double seconds = count / params.rate_hz;
    min_s = std::min(min_s, seconds);
    max_s = std::max(max_s, seconds);
    EXPECT_GE(seconds, params.fixation_min_s - 1e-9) << index;
    EXPECT_LE(seconds, params.fixation_max_s + 1e-9) << index;
  }
  // The durations spread over the range rather than all landing on one value.
  EXPECT_LT(min_s, 0.23);
  EXPECT_GT(max_s, 0.37);
  for (const auto& [index, count] : saccade_samples) {
    if (index == last - 1 || index == last) continue;
    EXPECT_EQ(count, 5) << index;  // 0.04 s at 120 Hz: a few samples between targets
  }
}

TEST(FixationModel, PointsStayInRegionPlusJitter) {
  FixationModelParams params;
  params.seed = 3;
  params.region_x0 = 0.1;
  params.region_x1 = 0.4;
  params.region_y0 = 0.6;
  params.region_y1 = 0.9;
  const double margin = 6.0 * params.jitter;  // 6 sigma: about 1 in 10^9 per coordinate
  const auto samples = runModel(params, 120 * 30);
  double min_x = 1, max_x = 0, min_y = 1, max_y = 0;
  for (const Labelled& s : samples) {
    EXPECT_GE(s.point.x, params.region_x0 - margin);
    EXPECT_LE(s.point.x, params.region_x1 + margin);
    EXPECT_GE(s.point.y, params.region_y0 - margin);
    EXPECT_LE(s.point.y, params.region_y1 + margin);
    min_x = std::min(min_x, s.point.x);
    max_x = std::max(max_x, s.point.x);
    min_y = std::min(min_y, s.point.y);
    max_y = std::max(max_y, s.point.y);
  }
  // Fixations visit the whole region.
  EXPECT_LT(min_x, 0.15);
  EXPECT_GT(max_x, 0.35);
  EXPECT_LT(min_y, 0.65);
  EXPECT_GT(max_y, 0.85);
}

TEST(FixationModel, FixationsHoldTargetWithJitterAndSaccadesMoveBetweenTargets) {
  FixationModelParams params;
  params.seed = 11;
  const auto samples = runModel(params, 120 * 20);
  // Per fixation: mean and spread of its points; the spread is the jitter sigma.
  std::map<std::uint64_t, std::vector<GazePoint>> fixations;
  for (const Labelled& s : samples) {
    if (s.phase == FixationSaccadeModel::Phase::kFixation) fixations[s.fixation].push_back(s.point);
  }
  double sum_sq = 0.0;
  int n = 0;
  for (const auto& [index, points] : fixations) {
    double mx = 0, my = 0;
    for (const GazePoint& p : points) mx += p.x, my += p.y;
    mx /= points.size();
    my /= points.size();
    for (const GazePoint& p : points) {
      sum_sq += (p.x - mx) * (p.x - mx) + (p.y - my) * (p.y - my);
      n += 2;
    }
  }
  const double sigma = std::sqrt(sum_sq / n);
  EXPECT_NEAR(sigma, params.jitter, 0.2 * params.jitter);
  // A saccade sample lies between the fixation it leaves and the next one (within a few jitter sigma
  // of the segment's bounding box).
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (samples[i].phase != FixationSaccadeModel::Phase::kSaccade) continue;
    const auto from = fixations.find(samples[i].fixation);
    const auto to = fixations.find(samples[i].fixation + 1);
    if (to == fixations.end()) continue;
    const auto mean = [](const std::vector<GazePoint>& pts, bool x) {
      double m = 0;
      for (const GazePoint& p : pts) m += x ? p.x : p.y;
      return m / pts.size();
    };
    const double x0 = mean(from->second, true), x1 = mean(to->second, true);
    const double y0 = mean(from->second, false), y1 = mean(to->second, false);
    const double tol = 0.01;
    EXPECT_GE(samples[i].point.x, std::min(x0, x1) - tol);
    EXPECT_LE(samples[i].point.x, std::max(x0, x1) + tol);
    EXPECT_GE(samples[i].point.y, std::min(y0, y1) - tol);
    EXPECT_LE(samples[i].point.y, std::max(y0, y1) + tol);
  }
}

TEST(FixationModel, PointsAreClampedToScreen) {
  FixationModelParams params;
  params.region_x0 = params.region_y0 = 0.0;
  params.region_x1 = params.region_y1 = 1.0;
  params.jitter = 0.2;  // huge jitter pushes many points past the edges
  const auto recording = gaze::synthesizeRecording(params, 10.0);
  int on_edge = 0;
  for (const GazePoint& p : recording.samples) {
    ASSERT_GE(p.x, 0.0);
    ASSERT_LE(p.x, 1.0);
    ASSERT_GE(p.y, 0.0);
    ASSERT_LE(p.y, 1.0);
    on_edge += (p.x == 0.0 || p.x == 1.0 || p.y == 0.0 || p.y == 1.0);
  }
  EXPECT_GT(on_edge, 0);
}

TEST(FixationModel, BlinksGiveShortInvalidGaps) {
  FixationModelParams params;
  params.blink_probability = 0.0;
  for (const GazePoint& p : gaze::synthesizeRecording(params, 10.0).samples) ASSERT_TRUE(p.valid);

  params.blink_probability = 1.0;  // every fixation blinks once
  const auto samples = runModel(params, 120 * 10);
  std::map<std::uint64_t, int> invalid_per_fixation;
  for (const Labelled& s : samples) {
    if (!s.point.valid) {
      EXPECT_EQ(s.phase, FixationSaccadeModel::Phase::kFixation);
      invalid_per_fixation[s.fixation]++;
    }
  }
  ASSERT_GT(invalid_per_fixation.size(), 10u);
  const auto last = invalid_per_fixation.rbegin()->first;
  for (const auto& [index, count] : invalid_per_fixation) {
    if (index != last) {
      EXPECT_EQ(count, 12) << index;  // blink_s 0.1 at 120 Hz
    }
  }
}

TEST(FixationModel, RecordingOfModelRoundTripsThroughFile) {
  FixationModelParams params;
  params.blink_probability = 0.2;
  const auto recording = gaze::synthesizeRecording(params, 5.0);
  gaze_test::TempFile file;
  gaze::writeGazeRecording(file.path(), recording);
  const auto read = gaze::readGazeRecording(file.path());
  ASSERT_EQ(read.samples.size(), recording.samples.size());
  for (std::size_t i = 0; i < read.samples.size(); ++i) {
    ASSERT_EQ(read.samples[i].x, recording.samples[i].x);
    ASSERT_EQ(read.samples[i].time_s, recording.samples[i].time_s);
  }
}

TEST(FixationModel, RejectsBadParameters) {
  const auto bad = [](auto change) {
    FixationModelParams params;
    change(params);
    return params;
  };
  EXPECT_THROW(FixationSaccadeModel(bad([](auto& p) { p.rate_hz = 0; })), std::invalid_argument);
  EXPECT_THROW(FixationSaccadeModel(bad([](auto& p) { p.rate_hz = std::nan(""); })), std::invalid_argument);
  EXPECT_THROW(FixationSaccadeModel(bad([](auto& p) { p.fixation_min_s = 0.5; })), std::invalid_argument);
  EXPECT_THROW(FixationSaccadeModel(bad([](auto& p) { p.fixation_min_s = 0.0001; })), std::invalid_argument);
  EXPECT_THROW(FixationSaccadeModel(bad([](auto& p) { p.saccade_s = -1; })), std::invalid_argument);
  EXPECT_THROW(FixationSaccadeModel(bad([](auto& p) { p.jitter = -0.1; })), std::invalid_argument);
  EXPECT_THROW(FixationSaccadeModel(bad([](auto& p) { p.region_x1 = 1.5; })), std::invalid_argument);
  EXPECT_THROW(FixationSaccadeModel(bad([](auto& p) { p.region_y0 = 0.9; })), std::invalid_argument);
  EXPECT_THROW(FixationSaccadeModel(bad([](auto& p) { p.blink_probability = 2; })), std::invalid_argument);
  EXPECT_THROW(gaze::synthesizeRecording(FixationModelParams{}, -1.0), std::invalid_argument);
  EXPECT_NO_THROW(FixationSaccadeModel(FixationModelParams{}));
}

TEST(FixationModel, ZeroSaccadeTimeJumpsStraightToNextFixation) {
  FixationModelParams params;
  params.saccade_s = 0.0;
  for (const Labelled& s : runModel(params, 1200)) EXPECT_EQ(s.phase, FixationSaccadeModel::Phase::kFixation);
}
