#include "study_trials.h"

#include <random>
#include <utility>

namespace viewer {

namespace {

// A draw in [0, n): the remainder's bias is below n / 2^64, nothing a study's order can show.
std::size_t below(std::mt19937_64& rng, std::size_t n) { return static_cast<std::size_t>(rng() % n); }

}  // namespace

std::vector<StudyTrial> makeTrials(const StudyPlan& plan, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<StudyTrial> trials;
  for (std::size_t s = 0; s < plan.scenes.size(); ++s) {
    for (std::size_t c = 0; c < plan.comparisons.size(); ++c) {
      for (int r = 0; r < plan.repetitions; ++r) {
        StudyTrial t;
        t.scene = s;
        t.comparison = c;
        t.repetition = r;
        const bool reference_first = below(rng, 2) == 0;
        t.intervals =
            reference_first ? std::array{Shown::kReference, Shown::kTest} : std::array{Shown::kTest, Shown::kReference};
        if (plan.question == StudyQuestion::kSameDifferent && below(rng, 2) == 0) {
          const Shown both = below(rng, 2) == 0 ? Shown::kReference : Shown::kTest;
          t.intervals = {both, both};
        }
        trials.push_back(t);
      }
    }
  }
  for (std::size_t i = trials.size(); i > 1; --i) std::swap(trials[i - 1], trials[below(rng, i)]);  // Fisher-Yates
  return trials;
}

const char* orderText(const StudyTrial& trial) {
  const bool first_reference = trial.intervals[0] == Shown::kReference;
  const bool second_reference = trial.intervals[1] == Shown::kReference;
  if (first_reference) return second_reference ? "RR" : "RT";
  return second_reference ? "TR" : "TT";
}

bool answerCorrect(StudyQuestion question, const StudyTrial& trial, int answer) {
  if (answer != 1 && answer != 2) return false;
  if (question == StudyQuestion::kTwoInterval) {
    return trial.intervals[static_cast<std::size_t>(answer - 1)] == Shown::kReference;
  }
  return (answer == 1) == trial.same();
}

}  // namespace viewer
