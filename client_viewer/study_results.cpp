#include "study_results.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "binomial_stats.h"

namespace viewer {

namespace {

// A CSV field: quoted, with quotes doubled, whenever it holds a separator, a quote or a line break.
std::string field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    quoted += c;
    if (c == '"') quoted += '"';
  }
  return quoted + "\"";
}

std::string number(double v, const char* format = "%.4f") {
  char text[64];
  std::snprintf(text, sizeof(text), format, v);
  return text;
}

struct GazeSummary {
  int frames = 0, tracking = 0;
  double mean_x = 0, mean_y = 0, spread = 0;  // spread: RMS distance from the mean, normalized units
};

GazeSummary gazeSummary(const std::array<IntervalRecord, 2>& intervals) {
  GazeSummary g;
  double sx = 0, sy = 0, sxx = 0, syy = 0;
  for (const IntervalRecord& r : intervals) {
    g.frames += r.frames;
    g.tracking += r.gaze_tracking_frames;
    sx += r.gaze_x_sum;
    sy += r.gaze_y_sum;
    sxx += r.gaze_xx_sum;
    syy += r.gaze_yy_sum;
  }
  if (g.tracking > 0) {
    g.mean_x = sx / g.tracking;
    g.mean_y = sy / g.tracking;
    g.spread =
        std::sqrt(std::max(0.0, sxx / g.tracking - g.mean_x * g.mean_x + syy / g.tracking - g.mean_y * g.mean_y));
  }
  return g;
}

}  // namespace

void writeTrialHeader(std::ostream& out) {
  out << "trial,seed,scene,comparison,reference,test,question,order,answer,correct,response_s,"
         "gaze_frames,gaze_tracking_share,gaze_mean_x,gaze_mean_y,gaze_spread,realtime_ratio_1,realtime_ratio_2\n";
}

void writeTrialRow(std::ostream& out, const StudyPlan& plan, std::uint64_t seed, const TrialRecord& r) {
  const StudyComparison& c = plan.comparisons[r.trial.comparison];
  const GazeSummary g = gazeSummary(r.intervals);
  const char* answer = plan.question == StudyQuestion::kTwoInterval ? (r.answer == 1 ? "1" : "2")
                                                                    : (r.answer == 1 ? "same" : "different");
  out << r.number << ',' << seed << ',' << field(plan.scenes[r.trial.scene]) << ',' << field(c.name) << ','
      << field(c.reference.label()) << ',' << field(c.test.label()) << ',' << questionName(plan.question) << ','
      << orderText(r.trial) << ',' << answer << ',' << (r.correct ? 1 : 0) << ',' << number(r.response_s, "%.3f") << ','
      << g.frames << ',' << number(g.frames > 0 ? static_cast<double>(g.tracking) / g.frames : 0.0, "%.3f") << ','
      << number(g.mean_x) << ',' << number(g.mean_y) << ',' << number(g.spread) << ','
      << number(r.intervals[0].realtime_ratio, "%.3f") << ',' << number(r.intervals[1].realtime_ratio, "%.3f") << '\n';
}

void writeSummary(std::ostream& out, const StudyPlan& plan, std::uint64_t seed,
                  const std::vector<TrialRecord>& records) {
  out << "study,seed,question,comparison,trials,correct,proportion_correct,wilson95_low,wilson95_high,"
         "binomial_p_two_sided\n";
  for (std::size_t c = 0; c < plan.comparisons.size(); ++c) {
    int trials = 0, correct = 0;
    for (const TrialRecord& r : records) {
      if (r.trial.comparison != c) continue;
      ++trials;
      correct += r.correct ? 1 : 0;
    }
    const Interval ci = wilsonInterval95(correct, trials);
    out << field(plan.name) << ',' << seed << ',' << questionName(plan.question) << ','
        << field(plan.comparisons[c].name) << ',' << trials << ',' << correct << ','
        << number(trials > 0 ? static_cast<double>(correct) / trials : 0.0) << ',' << number(ci.low) << ','
        << number(ci.high) << ',' << number(binomialTestP(correct, trials, 0.5), "%.6g") << '\n';
  }
}

}  // namespace viewer
