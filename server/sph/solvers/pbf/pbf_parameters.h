// pbf's own parameters (Macklin & Mueller 2013). SimParams (params.h) inherits them, so
// `params.pbf_iterations` reads as any other parameter; their rows of the settings table are
// pbfParameterRows, which param_table.cpp gathers.
#pragma once

#include <vector>

namespace sph {

struct ParamSpec;

struct PbfParams {
  // Relaxation and omega set the density constraint's passes (pbf_passes.h), which dfsph's local
  // placement runs too: they are pbf's, read by both.
  double pbf_relaxation = 0.01;
  // The full Jacobi step (1) overshoots: neighbours correct each other's density at the same time,
  // and a resting tank oscillates.
  double pbf_omega = 0.5;
  // The rest, pbf's solver step alone.
  int pbf_iterations = 3;
  double pbf_density_tolerance = 0.0;
  int pbf_max_iterations = 20;
  double pbf_tensile_k = 0.1;
  double pbf_tensile_dq = 0.2;
  int pbf_tensile_n = 4;
  double vorticity_confinement = 0.0;
};

// The rows of the fields above, in the order docs/parameters.md lists them.
std::vector<ParamSpec> pbfParameterRows();

}  // namespace sph
