// Figures for --report and the panel: render rate and frame-arrival-to-pixels times.
#pragma once

#include <algorithm>
#include <cstdio>
#include <vector>

namespace viewer {

class TimingReport {
 public:
  void addRender() { ++renders_; }
  void addArrivalToPixels(double ms) { arrival_to_pixels_ms_.push_back(ms); }
  // Prints one line to stdout (scripts parse it: key=value pairs).
  void print(double wall_seconds) const {
    std::vector<double> v = arrival_to_pixels_ms_;
    std::sort(v.begin(), v.end());
    auto pct = [&v](double p) {
      return v.empty() ? 0.0 : v[std::min(v.size() - 1, static_cast<std::size_t>(p * (v.size() - 1) + 0.5))];
    };
    double mean = 0.0;
    for (double x : v) mean += x;
    if (!v.empty()) mean /= static_cast<double>(v.size());
    std::printf(
        "sph_viewer report: renders=%llu wall_s=%.2f render_fps=%.1f frames_shown=%zu "
        "arrival_to_pixels_ms mean=%.2f p50=%.2f p99=%.2f max=%.2f\n",
        renders_, wall_seconds, wall_seconds > 0 ? static_cast<double>(renders_) / wall_seconds : 0.0, v.size(), mean,
        pct(0.5), pct(0.99), v.empty() ? 0.0 : v.back());
    std::fflush(stdout);
  }

 private:
  unsigned long long renders_ = 0;
  std::vector<double> arrival_to_pixels_ms_;
};

}  // namespace viewer
