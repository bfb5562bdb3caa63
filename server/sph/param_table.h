// The simulation parameters, each declared once: its scene-file key, type, valid range, which
// solvers read it and what it does. The scene loader, SimParams::validate, the programs' help,
// the control socket and the table in docs/fluids.md (parameterTableMarkdown, checked by a test)
// all read it; the defaults are the presets' (params.cpp).
#pragma once

#include <map>
#include <string>
#include <variant>
#include <vector>

#include "sph/params.h"

namespace sph {

// The SimParams field a parameter is; its alternative is the parameter's type.
using ParamField = std::variant<double SimParams::*, int SimParams::*, bool SimParams::*>;

struct ParamSpec {
  const char* key;      // in a scene file's "params", and everywhere a parameter is named
  const char* alias;    // a former key scene files may still use (with a warning), or nullptr
  const char* solvers;  // which solvers read it: "all", or a list of names
  ParamField field;
  double min;  // the valid range; flags: 0 and 1
  double max;
  bool min_open;  // min itself not allowed
  bool max_open;
  const char* description;  // one line

  bool isReal() const { return std::holds_alternative<double SimParams::*>(field); }
  bool isInteger() const { return std::holds_alternative<int SimParams::*>(field); }
  bool isFlag() const { return std::holds_alternative<bool SimParams::*>(field); }
  double get(const SimParams& p) const;
  // Sets the field, unchecked (check() first): integers and flags from their exact values.
  void set(SimParams& p, double value) const;
  // "" when `value` is one this parameter takes (finite, of its type, in range), else what it
  // takes, in the words of an error message: "must be in (0, 1]".
  std::string check(double value) const;
  // What it takes: "a number > 0", "an integer in [1, 100]", "true or false".
  std::string accepts() const;
};

const std::vector<ParamSpec>& parameterTable();
// By key or alias; nullptr when no parameter is called `name`.
const ParamSpec* findParameter(const std::string& name);

// One "KEY=VALUE" of a command line into `out` (by the parameter's key; flags take true, false, 1
// or 0). False with `error` in a user's words when it is not one.
bool parseParameterSetting(const std::string& setting, std::map<std::string, double>& out, std::string& error);

// A line a parameter, "  key  what it takes: what it is", for a program's --help.
std::string parameterHelpText();

// The table as Markdown, one row a parameter with its default in each preset (docs/fluids.md,
// "Parameters"; `sph_bench --parameter-table` prints it).
std::string parameterTableMarkdown();

}  // namespace sph
