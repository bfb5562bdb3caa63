// A study's trials in the order its participant sees them, from the plan and a seed alone: the
// same seed gives the same order, interval orders and same/different draws on any machine
// (std::mt19937_64's sequence is fixed by the C++ standard; the draws from it are this file's own).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "study_plan.h"

namespace viewer {

enum class Shown { kReference = 0, kTest = 1 };

struct StudyTrial {
  std::size_t scene = 0;       // index into StudyPlan::scenes
  std::size_t comparison = 0;  // index into StudyPlan::comparisons
  int repetition = 0;
  std::array<Shown, 2> intervals{Shown::kReference, Shown::kTest};
  bool same() const { return intervals[0] == intervals[1]; }
};

// scenes x comparisons x repetitions trials, shuffled. Two-interval trials show the reference in a
// random interval; same/different trials are "same" with probability one half (the reference or the
// test twice, at random) and otherwise both in a random order.
std::vector<StudyTrial> makeTrials(const StudyPlan& plan, std::uint64_t seed);

// "RT", "TR", "RR" or "TT": which condition each interval showed.
const char* orderText(const StudyTrial& trial);

// Whether an answer is right: two-interval `answer` 1 or 2 names the more detailed interval (the
// reference's); same/different `answer` 1 means "same", 2 "different".
bool answerCorrect(StudyQuestion question, const StudyTrial& trial, int answer);

}  // namespace viewer
