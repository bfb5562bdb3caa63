// A study's output: one CSV row per trial and a summary per comparison (binomial_stats.h). The
// seed that ordered the trials is in every row and in the summary, so a run can be repeated.
#pragma once

#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "study_plan.h"
#include "study_trials.h"

namespace viewer {

// What the viewer saw of one interval.
struct IntervalRecord {
  // Simulated over wall-clock seconds between the interval's first and last frames, as they
  // arrived here (any method; the server's governor measures only under foveated).
  double realtime_ratio = 0.0;
  int frames = 0;
  int gaze_tracking_frames = 0;  // frames whose step used a fresh gaze sample
  double gaze_x_sum = 0.0;       // of those frames' gaze points (normalized, origin top left)
  double gaze_y_sum = 0.0;
  double gaze_xx_sum = 0.0;
  double gaze_yy_sum = 0.0;
};

struct TrialRecord {
  int number = 0;  // 1-based, in the order shown
  StudyTrial trial;
  int answer = 0;  // 1 or 2 (two-interval: the interval; same/different: 1 same, 2 different)
  bool correct = false;
  double response_s = 0.0;  // from the question's onset to the key
  std::array<IntervalRecord, 2> intervals{};
};

void writeTrialHeader(std::ostream& out);
void writeTrialRow(std::ostream& out, const StudyPlan& plan, std::uint64_t seed, const TrialRecord& record);

// Per comparison: trials, correct, proportion, Wilson 95 % interval, exact two-sided binomial p
// against chance (one half for both questions); as CSV.
void writeSummary(std::ostream& out, const StudyPlan& plan, std::uint64_t seed,
                  const std::vector<TrialRecord>& records);

}  // namespace viewer
