#include "sph/solvers/pbf/pbf_solver.h"

#include <algorithm>
#include <cstdint>
#include <string>

#include "sph/collision.h"
#include "sph/phase_timer.h"
#include "sph/solvers/ordered_sum.h"
#include "sph/thread_share.h"

namespace sph {

namespace {

// pbf moves particles by position and holds them half a spacing off every wall, where a lattice
// beside a wall reads rho0 (IncompressibleSetup::contact).
const WallReach kWallContact(0.5f);

// At most this many frames relax fresh water (incompressible_setup.h).
constexpr int kSettleFrames = 200;

// A placed particle counts as in place once its density is within this of rest density (looser
// than the compression a deep tank keeps at rest, so placed particles in resting water are in
// place).
constexpr float kPlacedDensity = 1.01f;

// `placed` (particle_attributes.h): kPlacedThisFrame (kMark) in the frame after the adaptive step
// placed the particle, then kPlacedEarlier until it is in place. Its neighbours in that frame are
// kNearPlacement: what the constraint does to them then answers the placement too (without it the
// unmerged neighbours of a merge kicked a resting pool).

// Mean of rho / rho0 - 1 over the particles, where positive, as the constraint sees it (less the
// offsets: still_water_changes.h): what the tolerance bounds. Summed in a fixed order
// (ordered_sum.h), so the count of iterations it decides is the same for any thread count.
double meanCompression(const ParticleSet& p, float rest_density, std::vector<double>& partials) {
  if (p.size() == 0) return 0.0;
  const double sum = orderedSum(p.size(), partials, [&](std::size_t i) {
    const double density = static_cast<double>(p.density[i]) - p.density_offset[i];
    return std::max(density / rest_density - 1.0, 0.0);
  });
  return sum / static_cast<double>(p.size());
}

// Marks the neighbours of the fresh placements kNearPlacement (the order does not matter: one value).
void markNearPlacements(const NeighborGrid& grid, ParticleSet& p) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.placed[i] != kPlacedThisFrame) continue;
    for (std::uint32_t j : grid.neighbors(i)) {
      if (p.placed[j] == 0) p.placed[j] = kNearPlacement;
    }
  }
}

// Particles the adaptive step has just placed (split children, merged particles) sit where the
// split or merge put them, not where the water would. In the frame's first step, before the
// constraint, those compressed beyond this share of rest density more than their parent was (or
// than rest density, if more) are moved by position, with their neighbourhoods, for up to
// kPlacedIterations local iterations (local_placement.h): only they and their neighbours update
// their multipliers, and only the particles those reach move. Splitting every particle of a
// resting pool then compresses it far less than without the placement
// (SplitMerge.SplittingOrMergingARestingPbfPoolDoesNotKickIt); a handful of splits costs a handful
// of neighbourhoods, and the compression the flow itself brings (an impact) nothing.
constexpr float kPlacedCompression = 0.03f;
constexpr int kPlacedIterations = 21;

}  // namespace

PbfSolver::PbfSolver(const Scene& scene)
    : setup_(makeIncompressibleSetup(scene, kWallContact)), constants_(pbfConstantsOf(scene.params, setup_)) {
  const SimParams& p = scene.params;
  velocity_constants_.kernels = setup_.kernels;
  velocity_constants_.vorticity_epsilon = static_cast<float>(p.vorticity_confinement);
}

void PbfSolver::settle(const FrameContext& frame) { relaxAtRest(*this, frame, setup_, kSettleFrames); }

void PbfSolver::advance(const FrameContext& frame) {
  const int steps = frame.scene.params.substeps;
  const double dt = frame.dt / steps;
  frame.stats = SolverStats{};
  frame.stats.substeps = steps;
  ParticleSet& p = frame.particles;
  // The frame's pressure is the mean of its steps': where the iterations a step takes vary (the
  // density tolerance), one step's multipliers push more or less than the weight above them, and
  // the last step's alone misread a deep column's pressure slope, where the mean reads rho0 g.
  // Each step adds its pressure to pressure_sum_ (nothing reads p.pressure between the steps).
  pressure_sum_.reserve(p.capacity());
  pressure_sum_.assign(p.size(), 0.0f);
  for (int s = 0; s < steps; ++s) {
    substep(frame, frame.time + s * dt, static_cast<float>(dt), s == 0, s == steps - 1);
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.pressure[i] = pressure_sum_[i] / static_cast<float>(steps);
    p.pressure_term[i] = p.pressure[i] / (p.density[i] * p.density[i]);
  }
  // A placed particle stays placed, frame after frame, until the constraint holds it near rest
  // density (less its offset: still_water_changes.h): the rest of its correction is placement too.
  const auto in_place = static_cast<float>(kPlacedDensity * frame.scene.params.rest_density);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.placed[i] == 0) continue;
    p.placed[i] = p.placed[i] == kNearPlacement || p.density[i] - p.density_offset[i] <= in_place ? 0 : kPlacedEarlier;
  }
  StillWaterChanges::fade(p);
}

void PbfSolver::substep(const FrameContext& frame, double t0, float dt, bool first, bool last) {
  ParticleSet& p = frame.particles;
  const std::size_t n = p.size();
  const std::size_t room = p.capacity();
  for (auto* v : {&old_position_, &next_position_, &next_velocity_, &vorticity_, &wall_grad_}) {
    v->reserve(room);
    v->resize(n);
  }
  start_speed_.reserve(room);
  start_speed_.resize(n);
  lambda_.resize(n);
  lambda_step_.resize(n);
  constants_.box = frame.scene.boundary.stateAt(t0 + dt);
  constants_.obstacles = &frame.scene.boundary;
  velocity_constants_.dt = dt;
  const PbfPassForms forms = pbfPassForms();

  // Predict (MM13 algorithm 1, lines 1-4): gravity, then the positions it leads to.
  PhaseTimer timer(frame.timings.accel_integrate_collide_ms);
  const Vec3 gravity(0.0f, static_cast<float>(frame.scene.params.gravity), 0.0f);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    old_position_[i] = p.position[i];
    start_speed_[i] = p.velocity[i].norm();
    p.velocity[i] += dt * gravity;
    Vec3 x = p.position[i] + dt * p.velocity[i];
    Vec3 unused_velocity = Vec3::Zero();
    collideBoundary(frame.scene.boundary, constants_.box, constants_.contact[levelIndex(p.level[i])], x,
                    unused_velocity);
    p.position[i] = x;
  }

  timer.start(frame.timings.neighbor_ms);
  frame.grid.build(p);
  markNearPlacements(frame.grid, p);
  timer.stop();

  // The frame's fresh placements to their places (local_placement.h), by position: their start
  // positions move with them, so the step's velocities do not see the placement. In still water
  // the constraint then holds what the placement left, and the water takes it up slowly
  // (still_water_changes.h).
  PbfArrays a = pbfArraysOf(p, lambda_, lambda_step_, wall_grad_);
  if (first) {
    timer.start(frame.timings.density_pressure_ms);
    const bool placed = still_changes_.markDamped(p, frame.grid);
    frame.stats.placement_iterations +=
        placement_.placeFresh(p, frame.grid, LocalPlacement::Grid::kCurrent, constants_,
                              kPlacedCompression * constants_.rest_density, kPlacedIterations, old_position_);
    if (placed) still_changes_.holdChanges(p, frame.grid, start_speed_, a, constants_);
    timer.stop();
  }
  a.density_offset = p.density_offset.data();
  // Each lambda pass keeps the pairs' kernel gradient factor for the correction that follows it
  // at the same positions (a float a pair; keeping the three components of grad W cost more than
  // evaluating them again: docs/performance.md).
  pair_g_.resize(frame.grid.slotCount());
  a.pair_g = pair_g_.data();

  // Solve the density constraints (lines 8-19) from lambda = 0 (MM13), the artificial pressure
  // with the first correction. No warm start from the last step's multipliers: the constraint's
  // Jacobi system, like any symmetric SPH pressure stencil, has a near null space (a pressure
  // alternating layer by layer exerts no force inside the fluid) that the iterations neither see
  // nor damp, and carried from step to step it is felt where the walls and the surface break the
  // symmetry; a warm-started resting tank did not come to rest, it gained speed until it boiled.
  // From zero each step the multipliers are a function of the current compression alone, like a
  // stiff equation of state.
  // At least pbf_iterations; past them, on while the compression the last lambda pass measured
  // (before that iteration's correction, so one more than needed) exceeds the tolerance: a fixed
  // count carries the pressure only so many neighbourhoods a step, and deep water stays
  // compressed (docs/fluids.md, "pbf: position based fluids", iterations to a tolerance).
  timer.start(frame.timings.density_pressure_ms);
  std::fill_n(lambda_.begin(), n, 0.0f);
  const SimParams& params = frame.scene.params;
  const int least = params.pbf_iterations;
  const int most = std::max(least, params.pbf_max_iterations);
  int iterations = 0;
  bool more = true;
  while (more) {
    a.position = p.position.data()->data();
    forms.lambda(a, constants_, frame.grid);
    more = iterations + 1 < least ||
           (iterations + 1 < most && params.pbf_density_tolerance > 0.0 &&
            meanCompression(p, constants_.rest_density, sum_partials_) > params.pbf_density_tolerance);
    a.position_next = next_position_.data()->data();
    forms.correct(a, constants_, frame.grid, iterations == 0 && constants_.tensile_k > 0.0f);
    p.position.swap(next_position_);
    ++iterations;
  }
  frame.stats.iterations += iterations;
  timer.stop();

  // Velocities from the displacement (line 21), XSPH and vorticity confinement (line 22). A particle
  // the adaptive step placed (particle_attributes.h, `placed`) may be slowed or turned by its
  // correction but never made faster than its predicted velocity: the constraint moving a split's
  // children apart is placement, not motion, and made velocity it kicks a resting pool
  // (SplitMerge.SplittingOrMergingARestingPbfPoolDoesNotKickIt). Still water near a level change
  // keeps only part of it (still_water_changes.h).
  timer.start(frame.timings.accel_integrate_collide_ms);
  const float inv_dt = 1.0f / dt;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 step = p.position[i] - old_position_[i];
    Vec3 velocity = step * inv_dt;
    if (StillWaterChanges::damps(p, i, start_speed_[i])) velocity *= StillWaterChanges::kStillDamping;
    if (p.placed[i] != 0) {
      const float predicted = p.velocity[i].norm();
      const float speed = velocity.norm();
      if (speed > predicted) velocity *= predicted / speed;
    }
    p.velocity[i] = velocity;
  }
  // XSPH in the frame's last step for the whole frame (xsphOfFrame); confinement, a force, every
  // step (its pass's smoothing 0 in the others).
  const bool confinement = velocity_constants_.vorticity_epsilon > 0.0f;
  if (last || confinement) {
    velocity_constants_.xsph = last ? xsphOfFrame(frame.scene.params.xsph_viscosity, frame.stats.substeps) : 0.0f;
    const VelocityArrays v =
        velocityArraysOf(p, next_velocity_, vorticity_, confinement, last, frame.track_surface_distance);
    const VelocityPassForms velocity = velocityPassForms();
    velocity.smooth(v, velocity_constants_, frame.grid);
    if (confinement) velocity.confine(v, velocity_constants_, frame.grid);
    p.velocity.swap(next_velocity_);
  }

  // The attributes the rest of the step and the frames read: density (of the last constraint
  // pass), volume, and (added to pressure_sum_ for advance) the pressure whose impulse the
  // corrections were: dx_i = dt^2 a_i with a_i = -sum_j m_j (p_i / rho_i^2 + p_j / rho_j^2)
  // grad W_ij matches pbf_passes.h's dx term by term for lambda_i = -dt^2 m_i rho0 p_i / rho_i^2.
  const float rho0 = static_cast<float>(frame.scene.params.rest_density);
  double error = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : error)
  for (std::size_t i = 0; i < n; ++i) {
    pressure_sum_[i] += -lambda_[i] * p.density[i] * p.density[i] / (rho0 * p.mass[i] * dt * dt);
    p.volume[i] = p.mass[i] / p.density[i];
    error += std::max(p.density[i] / rho0 - 1.0f, 0.0f);
  }
  frame.stats.density_error = n > 0 ? static_cast<float>(error / static_cast<double>(n)) : 0.0f;
}

}  // namespace sph
