// The thesis's table 5.x layout for a matrix run: per scene (and preset), mean ms per phase (rows)
// per method (columns), steps per second and particle counts, plus each method's total as a ratio
// of regular; where a scene ran with several presets, their wall-clock seconds per simulated second
// side by side, as ratios of the first.
#pragma once

#include <string>
#include <vector>

#include "bench/bench_output.h"

namespace bench {

struct RunSummary {
  RunResult run;
  Summary summary;
};

// Markdown text; scenes, presets and methods in the order they first appear in `runs`.
std::string comparisonMarkdown(const std::vector<RunSummary>& runs);

}  // namespace bench
