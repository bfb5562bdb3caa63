#include "sph/solvers/pbf/pbf_parameters.h"

#include <limits>

#include "sph/param_table.h"

namespace sph {

std::vector<ParamSpec> pbfParameterRows() {
  using P = SimParams;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  return {
      {"pbf_relaxation", nullptr, "pbf, dfsph", &P::pbf_relaxation, 0, kInf, true, true, "",
       "constraint force mixing, relative to a full neighbourhood's (MM13 eq. 11); dfsph's placement too"},
      {"pbf_omega", nullptr, "pbf, dfsph", &P::pbf_omega, 0, 1, true, false, "",
       "relaxation of the Jacobi update, lambda += omega dlambda; dfsph's placement too"},
      {"pbf_iterations", nullptr, "pbf", &P::pbf_iterations, 1, 100, false, false, "",
       "least Jacobi iterations of the density constraint a solver step (MM13 algorithm 1)"},
      {"pbf_density_tolerance", nullptr, "pbf", &P::pbf_density_tolerance, 0, kInf, false, true, "",
       "past pbf_iterations, iterate on while the mean compression exceeds this; 0: exactly pbf_iterations"},
      {"pbf_max_iterations", nullptr, "pbf", &P::pbf_max_iterations, 1, 100, false, false, "",
       "most Jacobi iterations a solver step"},
      {"pbf_tensile_k", nullptr, "pbf", &P::pbf_tensile_k, 0, kInf, false, true, "",
       "k of the artificial pressure s_corr = -k (W(r) / W(dq h))^n (MM13 eq. 13); 0: off"},
      {"pbf_tensile_dq", nullptr, "pbf", &P::pbf_tensile_dq, 0, 1, true, true, "supports",
       "dq of the artificial pressure"},
      {"pbf_tensile_n", nullptr, "pbf", &P::pbf_tensile_n, 1, 8, false, false, "", "n of the artificial pressure"},
      {"vorticity_confinement", nullptr, "pbf", &P::vorticity_confinement, 0, kInf, false, true, "m/s",
       "epsilon of vorticity confinement (MM13 eq. 16); 0: off"},
  };
}

}  // namespace sph
