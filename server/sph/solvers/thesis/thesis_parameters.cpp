#include "sph/solvers/thesis/thesis_parameters.h"

#include <limits>

#include "sph/param_table.h"

namespace sph {

std::vector<ParamSpec> thesisParameterRows() {
  using P = SimParams;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  return {
      {"gas_stiffness", nullptr, "thesis", &P::gas_stiffness, 0, kInf, true, true, "m^2/s^2",
       "k of the state equation p = k (rho - rho0), eq. (3.12)"},
      {"viscosity", nullptr, "thesis", &P::viscosity, 0, kInf, false, true, "Pa s",
       "dynamic viscosity mu of the viscosity force, eq. (3.14)"},
      {"surface_tension", nullptr, "thesis", &P::surface_tension, 0, kInf, false, true, "N/m",
       "sigma of the surface-tension force, eqs. (3.16)-(3.19)"},
      {"surface_tension_enabled", nullptr, "thesis", &P::surface_tension_enabled, 0, 1, false, false, "",
       "surface tension where |n| >= l, eq. (3.36)"},
  };
}

}  // namespace sph
