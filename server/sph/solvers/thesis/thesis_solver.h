// The thesis's fluid (3.3-3.5): density and the state equation p = k (rho - rho0), pressure,
// viscosity, gravity and surface-tension forces, semi-implicit Euler, collisions: one step a frame.
#pragma once

#include <algorithm>

#include "sph/solvers/fluid_solver.h"
#include "sph/solvers/thesis/thesis_stages.h"

namespace sph {

class ThesisSolver : public FluidSolver {
 public:
  explicit ThesisSolver(const Scene& scene);
  void advance(const FrameContext& frame) override;
  // The lattice stays as the thesis started it; its density and pressure are computed, so that the
  // first frame shows the water's own (the first step computes them again).
  void settleFreshWater(const FrameContext& frame) override;
  double fillInset(double spacing, double radius) const override;
  // The thesis's stages know its two classes only (L0 and L1, (3.35)).
  int sizeLevels() const override { return kThesisLevels; }

 private:
  KernelTable kernels_;
};

}  // namespace sph
