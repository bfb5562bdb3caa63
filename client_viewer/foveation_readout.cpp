#include "foveation_readout.h"

#include <cstdio>

namespace viewer {

namespace {

template <typename... Args>
std::string format(const char* pattern, Args... args) {
  char line[256];
  std::snprintf(line, sizeof(line), pattern, args...);
  return line;
}

std::string realtimeText(const FoveationFigures& f) {
  return f.realtime_ratio > 0.0f ? format("%.2f of real time", static_cast<double>(f.realtime_ratio))
                                 : std::string("not measured");
}

std::string gainText(const FoveationFigures& f) {
  std::string text = format("q %.2f, g %.1f", static_cast<double>(f.quality), static_cast<double>(f.periphery_gain));
  if (f.atCeiling()) text += " (AT CEILING)";
  return text;
}

std::string budgetText(const FoveationFigures& f) {
  if (f.visible == 0) return "no visible water";
  return format("%.1f %% of %u visible over budget", 100.0 * f.over_budget / f.visible, f.visible);
}

std::string foveaText(const FoveationFigures& f) {
  if (!(f.fovea_width_arcmin > 0.0f)) return "gaze on no water";
  return format("particle %.2f' wide, eye resolves %.2f'", static_cast<double>(f.fovea_width_arcmin),
                static_cast<double>(f.fovea_mar_arcmin));
}

}  // namespace

const char* gazeStateText(gsph::v1::Method method, gsph::v1::GazeMode mode) {
  if (method == gsph::v1::METHOD_REGULAR || method == gsph::v1::METHOD_SURFACE || mode == gsph::v1::GAZE_MODE_NONE) {
    return "not used by the method";
  }
  switch (mode) {
    case gsph::v1::GAZE_MODE_TRACKING:
      return "tracking";
    case gsph::v1::GAZE_MODE_HOLDING:
      return "holding the last sample";
    case gsph::v1::GAZE_MODE_FALLBACK:
      return method == gsph::v1::METHOD_FOVEATED ? "lost: fovea at the screen's centre"
                                                 : "lost: surface refinement instead";
    default:
      return "-";
  }
}

std::string levelCountsText(const DecodedFrame& frame) {
  std::string text;
  for (std::size_t level = 0; level < frame.level_counts.size(); ++level) {
    text += format("%sL%zu %u", level == 0 ? "" : ", ", level, frame.level_counts[level]);
  }
  return text;
}

std::vector<std::string> foveationLines(const DecodedFrame& frame) {
  const FoveationFigures& f = frame.foveation;
  std::vector<std::string> lines;
  lines.push_back("real time  " + realtimeText(f));
  if (frame.method == gsph::v1::METHOD_FOVEATED) {
    lines.push_back("foveation  " + gainText(f));
    lines.push_back("budget     " + budgetText(f));
    lines.push_back("fovea      " + foveaText(f));
  }
  lines.push_back(std::string("gaze       ") + gazeStateText(frame.method, frame.gaze.mode));
  return lines;
}

std::string foveationLogLine(const DecodedFrame& frame) {
  const FoveationFigures& f = frame.foveation;
  std::string line = frame.scene + ": " + realtimeText(f);
  if (frame.method == gsph::v1::METHOD_FOVEATED) {
    line += "; " + gainText(f) + "; " + budgetText(f) + "; " + foveaText(f);
  }
  line += std::string("; gaze ") + gazeStateText(frame.method, frame.gaze.mode) + "; " + levelCountsText(frame);
  return line;
}

}  // namespace viewer
