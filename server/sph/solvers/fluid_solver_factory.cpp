#include "sph/solvers/fluid_solver_factory.h"

#include <map>
#include <stdexcept>

#include "sph/solvers/dfsph/dfsph_solver.h"
#include "sph/solvers/pbf/pbf_solver.h"
#include "sph/solvers/thesis/thesis_solver.h"

namespace sph {

namespace {

template <class S>
FluidSolverMaker maker() {
  return [](const Scene& scene) { return std::make_unique<S>(scene); };
}

std::map<std::string, FluidSolverMaker>& registry() {
  // The built-in solvers: adding one is a folder under solvers/ and a line here.
  static std::map<std::string, FluidSolverMaker> solvers = {
      {"thesis", maker<ThesisSolver>()},
      {"pbf", maker<PbfSolver>()},
      {"dfsph", maker<DfsphSolver>()},
  };
  return solvers;
}

}  // namespace

void registerFluidSolver(const std::string& name, FluidSolverMaker maker) { registry()[name] = std::move(maker); }

bool isFluidSolverName(const std::string& name) { return registry().contains(name); }

std::vector<std::string> fluidSolverNames() {
  std::vector<std::string> names;
  for (const auto& entry : registry()) names.push_back(entry.first);
  return names;
}

std::unique_ptr<FluidSolver> makeFluidSolver(const Scene& scene) {
  const auto it = registry().find(scene.params.solver);
  if (it == registry().end()) throw std::invalid_argument("no fluid solver named '" + scene.params.solver + "'");
  return it->second(scene);
}

}  // namespace sph
