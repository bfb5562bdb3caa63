#include "sph/solvers/dfsph/dfsph_parameters.h"

#include <limits>

#include "sph/param_table.h"

namespace sph {

std::vector<ParamSpec> dfsphParameterRows() {
  using P = SimParams;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  return {
      {"dfsph_cfl", "cfl", "dfsph", &P::dfsph_cfl, 0, 1, true, false, "",
       "no particle moves more than this share of its diameter in a solver step (BK17 eq. 15)"},
      {"dfsph_max_substeps", "max_substeps", "dfsph", &P::dfsph_max_substeps, 1, 1000, false, false, "",
       "most solver steps a frame"},
      {"dfsph_density_tolerance", "density_tolerance", "dfsph", &P::dfsph_density_tolerance, 0, kInf, true, true, "",
       "the constant-density solve stops at this mean compression after the step"},
      {"dfsph_divergence_tolerance", "divergence_tolerance", "dfsph", &P::dfsph_divergence_tolerance, 0, kInf, true,
       true, "", "the divergence solve stops at this mean |d rho / dt| / rho0 * dt"},
      {"dfsph_max_iterations", "max_iterations", "dfsph", &P::dfsph_max_iterations, 1, 10000, false, false, "",
       "most iterations of each solve a solver step"},
      {"dfsph_conjugate_gradients", "conjugate_gradients", "dfsph", &P::dfsph_conjugate_gradients, 0, 1, false, false,
       "", "the constant-density solve turns from Jacobi to conjugate gradients after three iterations"},
  };
}

}  // namespace sph
