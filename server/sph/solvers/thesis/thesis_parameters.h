// The thesis solver's own parameters: the forces of its weakly compressible fluid (table 3.1).
// SimParams (params.h) inherits them, so `params.gas_stiffness` reads as any other parameter;
// their rows of the settings table are thesisParameterRows, which param_table.cpp gathers.
#pragma once

#include <vector>

namespace sph {

struct ParamSpec;

struct ThesisParams {
  double viscosity = 3.5;
  double surface_tension = 0.0728;
  double gas_stiffness = 3.0;
  bool surface_tension_enabled = true;
};

// The rows of the fields above, in the order docs/parameters.md lists them.
std::vector<ParamSpec> thesisParameterRows();

}  // namespace sph
