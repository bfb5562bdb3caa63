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
      {"foveated_quality", &sph::AdaptiveConfig::foveated_quality},
      {"foveated_periphery_gain", &sph::AdaptiveConfig::foveated_periphery_gain},
      {"foveated_mar_w0_deg", &sph::AdaptiveConfig::foveated_mar_w0_deg},
      {"foveated_mar_slope", &sph::AdaptiveConfig::foveated_mar_slope},
      {"foveated_display_fov_deg", &sph::AdaptiveConfig::foveated_display_fov_deg},
      {"foveated_hidden_depth", &sph::AdaptiveConfig::foveated_hidden_depth},
      {"foveated_coarsen_margin", &sph::AdaptiveConfig::foveated_coarsen_margin},
      {"foveated_thin_fill", &sph::AdaptiveConfig::foveated_thin_fill},
      {"foveated_shallow_spread", &sph::AdaptiveConfig::foveated_shallow_spread},
      {"foveated_merge_hold_s", &sph::AdaptiveConfig::foveated_merge_hold_s},
      {"foveated_thin_level", &sph::AdaptiveConfig::foveated_thin_level},
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

std::string adaptiveParameterNames() {
  std::string names;
  for (const auto& entry : doubleFields()) names += (names.empty() ? "" : ", ") + entry.first;
  return names + ", surface_includes_walls";
}

bool parseAdaptiveSetting(const std::string& setting, std::map<std::string, double>& overrides, std::string& error) {
  const auto eq = setting.find('=');
  if (eq == std::string::npos || eq == 0) {
    error = "expected NAME=VALUE";
    return false;
  }
  const std::string name = setting.substr(0, eq);
  const std::string value = setting.substr(eq + 1);
  double number = 0.0;
  std::size_t used = 0;
  try {
    number = std::stod(value, &used);
  } catch (const std::exception&) {
    used = 0;  // std::stod's own message ("stod") means nothing to a user
  }
  if (used == 0 || used != value.size()) {
    error = "expected a number after '=', got '" + value + "'";
    return false;
  }
  sph::AdaptiveConfig probe;
  bool known = false;
  error = setAdaptiveParameter(probe, name, number, known);
  if (!known) error = "unknown setting '" + net::echoText(name) + "'; known: " + adaptiveParameterNames();
  if (!error.empty()) return false;
  overrides[name] = number;
  return true;
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
