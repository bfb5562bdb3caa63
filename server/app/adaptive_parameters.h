// The adaptive settings by name, as control requests (set_parameters) and the command line name them.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "sph/adaptive/method.h"

namespace app {

// Sets one AdaptiveConfig field by name (booleans take 0 or 1). Returns "" on success, else why not;
// `known` is false when the name is not an adaptive setting at all. Does not validate the whole config.
std::string setAdaptiveParameter(sph::AdaptiveConfig& config, const std::string& name, double value, bool& known);
// The current values by name.
void adaptiveParameters(const sph::AdaptiveConfig& config, std::map<std::string, double>& out);
// The names setAdaptiveParameter knows, comma-separated (for messages).
std::string adaptiveParameterNames();
// Parses one command-line "NAME=VALUE" into `overrides`; false with `error` in a user's words (an
// unknown name lists the known ones) when it is not one.
bool parseAdaptiveSetting(const std::string& setting, std::map<std::string, double>& overrides, std::string& error);
// Applies every override, then AdaptiveConfig::validate; throws std::invalid_argument naming the first bad one.
sph::AdaptiveConfig withOverrides(sph::AdaptiveConfig config, const std::map<std::string, double>& overrides);

}  // namespace app
