// What pbf and dfsph derive from a scene once: each class's cubic kernel, rest lattice spacing and
// wall contact distance, the walls' volume (boundary_volume.h), and the sums of a full resting
// neighbourhood that scale their solvers.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "sph/boundary_volume.h"
#include "sph/collision.h"
#include "sph/kernels.h"
#include "sph/particles.h"
#include "sph/scene.h"
#include "sph/solvers/fluid_solver.h"
#include "sph/solvers/pair_kernels.h"
#include "sph/solvers/velocity_passes.h"

namespace sph {

struct IncompressibleSetup {
  PairKernels kernels;                      // each class's kernel and particle mass
  std::array<float, kMaxLevels> spacing{};  // cbrt(m / rho0): a resting lattice's
  // The nearest a particle's centre may come to the floor and to the other walls (the solver's
  // choice, in spacings: makeIncompressibleSetup). The one-sided walls hold settled water only by
  // compressing it, so its wall layers come to rest on these distances, not where the walls'
  // density would put them; the closer they sit, the more of the water's volume the walls swallow.
  std::array<WallReach, kMaxLevels> contact{};
  // On a resting lattice of the class: sum_j m_j |grad W_ij|^2 (the gradient sum itself vanishes
  // by symmetry).
  std::array<double, kMaxLevels> lattice_grad_sq{};
  std::unique_ptr<BoundaryVolume> boundary;
};

// `contact_spacings`: IncompressibleSetup::contact in lattice spacings of each class.
IncompressibleSetup makeIncompressibleSetup(const Scene& scene, WallReach contact_spacings = WallReach(0.5f));

// Fresh water of `Solver`'s kind relaxes to rest where the scene puts it: inside a gate, the water
// region's faces as walls (gatedScene, with their density: boundary_volume.h), so that a dam-break
// column settles standing and is released at t = 0 instead of collapsing while it settles. The
// settled packing and what the solver keeps per particle (its warm start) carry over.
template <class Solver>
void settleInGate(const FrameContext& frame) {
  const Scene gated = gatedScene(frame.scene);
  Solver gate(gated);
  gate.settle({gated, frame.particles, frame.grid, 0.0, gated.params.time_step, false, frame.timings, frame.stats});
}

// The pressure of water at rest, rho0 |g| (y_top - y), y_top the top face of the highest layer:
// the solvers' warm start for a fresh lattice (settle()).
std::vector<float> restingPressure(const Scene& scene, const IncompressibleSetup& setup, const ParticleSet& particles);

// Relaxes fresh water quasi-statically: frames of `solver` with the velocities set back to zero
// after each, until no particle moves more than a thousandth of a spacing in a frame (or, for
// water that never comes to rest, `max_frames`). The result is the packing and the pressure in
// which the solver itself holds the water at rest. Returns the frames taken.
int relaxAtRest(FluidSolver& solver, const FrameContext& frame, const IncompressibleSetup& setup, int max_frames);

// The velocity passes' view of `p` as it is now, with the solver's scratch for the smoothed
// velocities and the vorticity (sized to p.size()). The vorticity only with `confinement`; |n| and
// the surface-distance hop only in the frame's last step (`last_step`: what the adaptive step
// reads after the frame), the hop only when tracked.
VelocityArrays velocityArraysOf(ParticleSet& p, std::vector<Vec3>& velocity_next, std::vector<Vec3>& vorticity,
                                bool confinement, bool last_step, bool track_surface_distance);

// A frame's scratch array sized to n without shrinking (no allocation once at the ceiling).
template <typename T>
void sizeScratch(std::vector<T>& v, std::size_t n) {
  if (v.size() < n) v.resize(n);
}

}  // namespace sph
