#include "app/adaptive_parameters.h"

#include <cmath>
#include <stdexcept>

#include "net/peer_text.h"

namespace app {
namespace {

const std::map<std::string, double sph::AdaptiveConfig::*>& doubleFields() {
  static const std::map<std::string, double sph::AdaptiveConfig::*> fields = {
      {"gaze_radius", &sph::AdaptiveConfig::gaze_radius},
      {"gaze_ring_radius", &sph::AdaptiveConfig::gaze_ring_radius},
      {"gaze_ring", &sph::AdaptiveConfig::gaze_ring_radius},  // the schema comment's short name
      {"gaze_stale_s", &sph::AdaptiveConfig::gaze_stale_s},
      {"gaze_hold_s", &sph::AdaptiveConfig::gaze_hold_s},
      {"alpha", &sph::AdaptiveConfig::alpha},
      {"beta", &sph::AdaptiveConfig::beta},
      {"gamma", &sph::AdaptiveConfig::gamma},
      {"threshold", &sph::AdaptiveConfig::threshold},
      {"surface_normal_scale", &sph::AdaptiveConfig::surface_normal_scale},
  };
  return fields;
}

}  // namespace

std::string setAdaptiveParameter(sph::AdaptiveConfig& config, const std::string& name, double value, bool& known) {
  known = true;
  if (!std::isfinite(value)) return "parameter '" + net::echoText(name) + "' is not finite";
  const auto& fields = doubleFields();
  if (const auto it = fields.find(name); it != fields.end()) {
    config.*(it->second) = value;
    return {};
  }
  if (name == "surface_includes_walls") {
    if (value != 0.0 && value != 1.0) return name + " must be 0 or 1";
    config.surface_includes_walls = value == 1.0;
    return {};
  }
  known = false;
  return "unknown parameter '" + net::echoText(name) + "'";
}

void adaptiveParameters(const sph::AdaptiveConfig& config, std::map<std::string, double>& out) {
  for (const auto& [name, field] : doubleFields()) {
    if (name != "gaze_ring") out[name] = config.*field;
  }
  out["surface_includes_walls"] = config.surface_includes_walls ? 1.0 : 0.0;
}

sph::AdaptiveConfig withOverrides(sph::AdaptiveConfig config, const std::map<std::string, double>& overrides) {
  for (const auto& [name, value] : overrides) {
    bool known = false;
    const std::string error = setAdaptiveParameter(config, name, value, known);
    if (!error.empty()) throw std::invalid_argument(error);
  }
  config.validate();
  return config;
}

}  // namespace app
