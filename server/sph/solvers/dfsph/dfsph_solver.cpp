#include "sph/solvers/dfsph/dfsph_solver.h"

#include <algorithm>
#include <cmath>

#include "sph/collision.h"
#include "sph/phase_timer.h"
#include "sph/simd/simd_level.h"

namespace sph {

namespace {

// dfsph moves particles by velocity: it holds them half a spacing off the floor, whose layer its
// constant-density solve holds (floor_contact.h), and 0.3 of a spacing off the side walls and
// obstacles, where the layer above the floor, pressed sideways onto a guard beside a vertical
// edge, would otherwise compress (IncompressibleSetup::contact).
const WallReach kWallContact(0.5f, 0.3f);

// The divergence solver leaves particles with fewer neighbours alone (BK17 4.2: at the surface
// the divergence cannot be estimated from one side); a full resting neighbourhood has about 33.
constexpr std::uint32_t kDivergenceNeighbours = 20;

// Jacobi relaxation (SPlisHSPlasH's, and IISPH's): the diagonal alone overestimates a particle's
// say over its own density, since its neighbours move too.
constexpr float kRelaxation = 0.5f;

// Jacobi iterations before the constant-density solve turns to conjugate gradients
// (DfsphSolver::conjugateGradients). The divergence solve, a few iterations a step, stays Jacobi:
// conjugate gradients there took more iterations in both solves (dam break).
constexpr int kJacobiIterations = 3;

// Fresh placements are moved apart (local_placement.h) until none sits more than this share of
// rest density above its parent's density (or rho0), in at most this many iterations. The solver
// turns what compression is left into speed within one step: splitting every particle of a moving
// pool threw it without the placement, and a looser limit still kicked it. Splitting a whole
// resting pool takes most of these iterations to reach the limit (the wall layers' children crowd
// their layer); stopped short of it, many children were still over it and the step lifted the pool
// (SplitMerge.SplittingOrMergingARestingDfsphPoolDoesNotThrowIt). The dam break's splits take fewer.
constexpr float kPlacedCompression = 0.003f;
constexpr int kPlacedIterations = 300;

}  // namespace

DfsphSolver::DfsphSolver(const Scene& scene)
    : setup_(makeIncompressibleSetup(scene, kWallContact)), placement_constants_(pbfConstantsOf(scene.params, setup_)) {
  constants_.kernels = setup_.kernels;
  constants_.rest_density = static_cast<float>(scene.params.rest_density);
  constants_.boundary = setup_.boundary.get();
  velocity_constants_.kernels = setup_.kernels;
}

// Only the warm start: the quasi-static relaxation pbf settles with (relaxAtRest) does not
// converge for this solver (in the Martin & Moyce gate it left the column taller than it was
// sampled, in a closed deep tank it gave NaN; docs/fluids.md, "Water starts at rest"); the lattice
// is released as sampled, with the pressure of water at rest.
void DfsphSolver::settle(const FrameContext& frame) {
  const std::vector<float> pressure = restingPressure(frame.scene, setup_, frame.particles);
  const auto rho0 = static_cast<float>(frame.scene.params.rest_density);
  for (std::size_t i = 0; i < frame.particles.size(); ++i) frame.particles.kappa[i] = pressure[i] / (rho0 * rho0);
}

void DfsphSolver::advance(const FrameContext& frame) {
  ParticleSet& p = frame.particles;
  const SimParams& params = frame.scene.params;
  frame.stats = SolverStats{};
  frame.stats.substeps = 0;
  placeFresh(frame);
  double done = 0.0;
  const float spacing = std::min(setup_.spacing[0], setup_.spacing[1]);
  while (done < frame.dt * (1.0 - 1e-9)) {
    // CFL: no particle moves more than cfl spacings in a step (BK17 eq. 15 with the diameter),
    // and at least `substeps` steps a frame (SPlisHSPlasH's 5 ms ceiling: a tank at rest in 10 ms
    // steps did not come to rest; docs/fluids.md, "dfsph: divergence-free SPH").
    float fastest = 0.0f;
    const std::size_t n = p.size();
#pragma omp parallel for schedule(static) reduction(max : fastest)
    for (std::size_t i = 0; i < n; ++i) fastest = std::max(fastest, p.velocity[i].norm());
    const double remaining = frame.dt - done;
    const double longest = frame.dt / params.substeps;
    const double bound = fastest > 0.0f ? std::min(params.dfsph_cfl * spacing / fastest, longest) : longest;
    const int left = std::max(params.dfsph_max_substeps - frame.stats.substeps, 1);
    const int steps = std::clamp(static_cast<int>(std::ceil(remaining / bound - 1e-9)), 1, left);
    const double dt = remaining / steps;
    ++frame.stats.substeps;  // counted before it runs: the last step's XSPH reads the frame's count
    substep(frame, frame.time + done, static_cast<float>(dt), steps == 1);
    done += dt;
  }
}

void DfsphSolver::placeFresh(const FrameContext& frame) {
  PhaseTimer timer(frame.timings.density_pressure_ms);
  placement_constants_.box = frame.scene.boundary.stateAt(frame.time);
  placement_constants_.obstacles = &frame.scene.boundary;
  frame.stats.placement_iterations +=
      placement_.placeFresh(frame.particles, frame.grid, LocalPlacement::Grid::kBuild, placement_constants_,
                            kPlacedCompression * constants_.rest_density, kPlacedIterations);
}

void DfsphSolver::pressureAccelerations(const DfsphPassForms& forms, const NeighborGrid& grid, bool held) {
  forms.acceleration(arrays_, constants_, grid);
  if (held) floor_.hold(acceleration_);
}

int DfsphSolver::solve(const FrameContext& frame, std::vector<float>& warm, bool density_target, float dt) {
  ParticleSet& p = frame.particles;
  const std::size_t n = p.size();
  const DfsphPassForms forms = dfsphPassForms();
  const float rho0 = constants_.rest_density;
  const SimParams& params = frame.scene.params;
  // The floor holds the particles on it, and the constant-density solve knows (floor_contact.h).
  if (density_target) floor_.find(p, constants_.box, setup_.contact, setup_.spacing, dt);
  // What the velocities alone would do: the density after the step (rho + dt D(v)), or its rate.
  arrays_.field = p.velocity.data()->data();
  arrays_.with_wall_rate = true;
  forms.change(arrays_, constants_, frame.grid);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const bool counted = density_target || frame.grid.neighborCount(i) >= kDivergenceNeighbours;
    // The pressure must undo this much: rho0 - rho_adv (density), -D(v) (divergence). As in
    // SPlisHSPlasH, the density's target is not clamped (an under-dense particle asks for
    // expansion, which k >= 0 below cannot give, so it gets no pressure and no pull), and the
    // divergence's is (where the velocities do not compress, the rate is left as it is). With the
    // density's clamped to no expansion, water in a closed box (the settle's gate) has nowhere to
    // put the compression its fall makes: the system has no solution and k climbs uniformly.
    target_[i] = !counted         ? 0.0f
                 : density_target ? rho0 - (p.density[i] + dt * change_[i])
                                  : -std::max(change_[i], 0.0f);
    stiffness_[i] = target_[i] < 0.0f ? warm[i] : 0.0f;  // warm start (BK17 4.3)
  }
  // The pressure acceleration a(k) changes the density after the step by dt^2 D(a) (its rate by
  // dt D(a)); Jacobi on A k = target, A's diagonal -dt^2 / inverse_diagonal (dfsph_passes.h).
  const float scale = density_target ? dt * dt : dt;
  const float tolerance =
      static_cast<float>(density_target ? params.dfsph_density_tolerance : params.dfsph_divergence_tolerance / dt) *
      rho0;
  arrays_.field = acceleration_.data()->data();
  arrays_.with_wall_rate = false;
  const int least = density_target ? 2 : 1;  // BK17 runs at least two density iterations, one divergence iteration
  const double count = static_cast<double>(std::max<std::size_t>(n, 1));
  int iteration = 0;
  bool accelerated = false;  // whether the iterations turned to conjugate gradients yet
  while (iteration < params.dfsph_max_iterations) {
    pressureAccelerations(forms, frame.grid, density_target);
    forms.change(arrays_, constants_, frame.grid);
    if (density_target && params.dfsph_conjugate_gradients && !accelerated && iteration == kJacobiIterations) {
      // Jacobi removes a step's new, local error in a few iterations, but the smooth rest only
      // slowly (on the dam break most of a solve's iterations went to it); conjugate gradients
      // take it from here, and the Jacobi iterations resume on what they leave (the k < 0 they
      // drop, a rougher residual).
      iteration = conjugateGradients(frame, forms, scale, tolerance, least, iteration);
      accelerated = true;
      continue;
    }
    double error = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : error)
    for (std::size_t i = 0; i < n; ++i) {
      const float residual = target_[i] - scale * change_[i];  // < 0: still compressed
      stiffness_[i] = std::max(stiffness_[i] - kRelaxation * residual * inverse_diagonal_[i] / scale, 0.0f);
      error += std::max(-residual, 0.0f);
    }
    ++iteration;
    // BK17's order: the iteration that finds the error within still updates (after conjugate
    // gradients that update smooths what they leave: stopping before it, the next step's
    // divergence solve took more iterations on the dam break).
    if (error / count <= tolerance && iteration >= least) break;
  }
  pressureAccelerations(forms, frame.grid, density_target);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    p.velocity[i] += dt * acceleration_[i];
    warm[i] = stiffness_[i];
  }
  if (density_target) floor_.relaxSlip(p);
  return iteration;
}

void DfsphSolver::substep(const FrameContext& frame, double t0, float dt, bool last) {
  ParticleSet& p = frame.particles;
  const std::size_t n = p.size();
  const std::size_t room = p.capacity();
  for (auto* v : {&boundary_grad_, &next_velocity_, &vorticity_, &acceleration_}) {
    v->reserve(room);
    v->resize(n);
  }
  for (auto* v : {&inverse_diagonal_, &wall_rate_, &change_, &target_, &stiffness_}) {
    v->reserve(room);
    v->resize(n);
  }
  constants_.box = frame.scene.boundary.stateAt(t0 + dt);
  velocity_constants_.dt = dt;

  PhaseTimer timer(frame.timings.neighbor_ms);
  frame.grid.build(p);
  arrays_.pair_grad = pair_grad_.fit(frame.grid);
  timer.stop();

  DfsphArrays& a = arrays_;
  a.n = n;
  a.mass = p.mass.data();
  a.support = p.support.data();
  a.class_index = reinterpret_cast<const std::uint8_t*>(p.level.data());
  a.position = p.position.data()->data();
  a.density = p.density.data();
  a.inverse_diagonal = inverse_diagonal_.data();
  a.boundary_grad = boundary_grad_.data()->data();
  a.boundary_wall_rate = wall_rate_.data();
  a.change = change_.data();
  a.stiffness = stiffness_.data();
  a.acceleration = acceleration_.data()->data();

  // Densities, then the divergence solver on the new neighbourhoods (BK17 algorithm 1).
  timer.start(frame.timings.density_pressure_ms);
  dfsphPassForms().density(a, constants_, frame.grid);
  if (frame.scene.params.dfsph_divergence_tolerance > 0.0) {
    frame.stats.divergence_iterations += solve(frame, p.kappa_divergence, false, dt);
  }

  // Gravity, and in the frame's last step XSPH viscosity for the whole frame (xsphOfFrame; with
  // |n| and the surface-distance hop for the adaptive step).
  timer.start(frame.timings.accel_integrate_collide_ms);
  const Vec3 gravity(0.0f, static_cast<float>(frame.scene.params.gravity), 0.0f);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) p.velocity[i] += dt * gravity;
  if (last) {
    velocity_constants_.xsph = xsphOfFrame(frame.scene.params.xsph_viscosity, frame.stats.substeps);
    const VelocityArrays v = velocityArraysOf(p, next_velocity_, vorticity_, false, true, frame.track_surface_distance);
    velocityPassForms().smooth(v, velocity_constants_, frame.grid);
    p.velocity.swap(next_velocity_);
  }

  // The constant-density solver.
  timer.start(frame.timings.density_pressure_ms);
  frame.stats.iterations += solve(frame, p.kappa, true, dt);

  // Positions, kept inside (a guard), and the attributes the frames and the adaptive step read.
  timer.start(frame.timings.accel_integrate_collide_ms);
  const float rho0 = constants_.rest_density;
  double error = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : error)
  for (std::size_t i = 0; i < n; ++i) {
    Vec3 x = p.position[i] + dt * p.velocity[i];
    collideBoundary(frame.scene.boundary, constants_.box, setup_.contact[levelIndex(p.level[i])], x, p.velocity[i]);
    p.position[i] = x;
    p.pressure[i] = p.kappa[i] * p.density[i] * p.density[i];  // k = p / rho^2
    p.volume[i] = p.mass[i] / p.density[i];
    p.pressure_term[i] = p.kappa[i];
    error += std::max(p.density[i] / rho0 - 1.0f, 0.0f);
  }
  frame.stats.density_error = n > 0 ? static_cast<float>(error / static_cast<double>(n)) : 0.0f;
}

}  // namespace sph
