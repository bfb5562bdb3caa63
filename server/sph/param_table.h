// Every setting a user can set, each declared once: the simulation parameters (SimParams, a scene
// file's "params") and the adaptive settings (AdaptiveConfig, its "adaptive"), with key, type,
// valid range, unit, who reads it and what it does. The scene loader, SimParams::validate,
// AdaptiveConfig::validate, the programs' --param, --adaptive and --help, the control socket's
// set_parameters and the tables in docs/parameters.md (parameterTableMarkdown, checked by a test) all
// read it; the defaults are the presets' (params.cpp) and AdaptiveConfig's (adaptive/method.h).
#pragma once

#include <map>
#include <string>
#include <variant>
#include <vector>

#include "sph/adaptive/method.h"
#include "sph/params.h"

namespace sph {

// The field a setting is, in SimParams or (the last three) in AdaptiveConfig; its alternative is
// the setting's type.
using ParamField = std::variant<double SimParams::*, int SimParams::*, bool SimParams::*, double AdaptiveConfig::*,
                                int AdaptiveConfig::*, bool AdaptiveConfig::*>;

struct ParamSpec {
  const char* key;      // in a scene file, and everywhere a setting is named
  const char* alias;    // a former key that still works (a scene file's with a warning), or nullptr
  const char* read_by;  // which solvers ("all", or a list) or adaptive methods read it
  ParamField field;
  double min;  // the valid range; flags: 0 and 1
  double max;
  bool min_open;  // min itself not allowed
  bool max_open;
  const char* unit;         // "" for a plain number
  const char* description;  // one line

  // An AdaptiveConfig field (a scene file's "adaptive"), else a SimParams one ("params").
  bool isAdaptive() const;
  bool isReal() const;
  bool isInteger() const;
  bool isFlag() const;
  // The value of this setting's field, from the struct that holds it; the other throws
  // std::logic_error.
  double get(const SimParams& p) const;
  double get(const AdaptiveConfig& c) const;
  // Sets the field, unchecked (check() first): integers and flags from their exact values.
  void set(SimParams& p, double value) const;
  void set(AdaptiveConfig& c, double value) const;
  // "" when `value` is one this setting takes (finite, of its type, in range), else what it takes,
  // in the words of an error message: "must be a number in (0, 1]".
  std::string check(double value) const;
  // What it takes: "a number > 0", "an integer in [1, 100]", "true or false".
  std::string accepts() const;
};

// The simulation parameters first, then the adaptive settings.
const std::vector<ParamSpec>& parameterTable();
// By key or alias; nullptr when no setting is called `name`.
const ParamSpec* findParameter(const std::string& name);

// Adds a row (a test's setting) to the table; throws std::invalid_argument when its key or alias
// names a setting already. Not thread-safe, and it may move the rows: register before anything
// reads the table.
void registerParameter(const ParamSpec& spec);
// Removes the row a registerParameter call added; false when there is none called `key`.
bool unregisterParameter(const std::string& key);

// Throws std::invalid_argument "parameter 'KEY' must be ..." for the first field of `config` that
// is outside its row's range (AdaptiveConfig::validate's first check).
void checkRanges(const AdaptiveConfig& config);

// One "KEY=VALUE" of a command line into `out` (by the setting's key; flags take true, false, 1 or
// 0). False with `error` in a user's words when it is not one.
bool parseParameterSetting(const std::string& setting, std::map<std::string, double>& out, std::string& error);

// `values` (by key or alias, all adaptive settings) onto `config`, then AdaptiveConfig::validate;
// throws std::invalid_argument naming the first bad one.
AdaptiveConfig withAdaptiveSettings(AdaptiveConfig config, const std::map<std::string, double>& values);

// A line a setting of one kind (adaptive or not), "  key  (read by) what it takes: what it is",
// for a program's --help.
std::string parameterHelpText(bool adaptive);

// The table as Markdown: the simulation parameters with their default in each preset, then the
// adaptive settings with theirs (docs/parameters.md; `sph_bench --parameter-table`
// prints it).
std::string parameterTableMarkdown();

}  // namespace sph
