// dfsph's own parameters (Bender & Koschier 2015, 2017). SimParams (params.h) inherits them, so
// `params.dfsph_cfl` reads as any other parameter; their rows of the settings table are
// dfsphParameterRows, which param_table.cpp gathers.
#pragma once

#include <vector>

namespace sph {

struct ParamSpec;

struct DfsphParams {
  double dfsph_cfl = 0.4;
  int dfsph_max_substeps = 40;
  double dfsph_density_tolerance = 5e-4;
  double dfsph_divergence_tolerance = 1e-3;
  int dfsph_max_iterations = 100;
  bool dfsph_conjugate_gradients = false;
};

// The rows of the fields above, in the order docs/parameters.md lists them.
std::vector<ParamSpec> dfsphParameterRows();

}  // namespace sph
