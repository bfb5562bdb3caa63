// The fluid solvers by name: SimParams::solver names the one a scene runs. The built-in solvers
// are registered in fluid_solver_factory.cpp, a line each; registerFluidSolver adds another (a
// test's, a plug-in's) without touching the library.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sph/solvers/fluid_solver.h"

namespace sph {

using FluidSolverMaker = std::function<std::unique_ptr<FluidSolver>(const Scene& scene)>;

// Adds (or replaces) the solver called `name`. Not thread-safe: register before simulations start.
void registerFluidSolver(const std::string& name, FluidSolverMaker maker);
bool isFluidSolverName(const std::string& name);
std::vector<std::string> fluidSolverNames();

// The solver of `scene.params.solver`, set up for the scene's boundary (the frames must bring the
// same scene). Throws std::invalid_argument for a name no solver is registered under.
std::unique_ptr<FluidSolver> makeFluidSolver(const Scene& scene);

}  // namespace sph
