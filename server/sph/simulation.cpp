#include "sph/simulation.h"

#include <algorithm>
#include <chrono>

namespace sph {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

Simulation::Simulation(const Scene& scene, SizeClass start_class, std::size_t capacity)
    : scene_(scene), kernels_(makeKernelTable(scene.params)), particles_(capacity), start_class_(start_class) {
  scene_.params.validate();
  fillWater(scene_, start_class, particles_);
  configureGrid(false);
  solver_ = makeFluidSolver(scene_);
  if (scene_.params.solver == Solver::kThesis) {
    solver_->settle({scene_, particles_, grid_, 0.0, scene_.params.time_step, false, timings_, solver_stats_});
  } else {
    // Fresh water relaxes to rest where the scene puts it: inside a gate, the water region's faces
    // as walls (with their density, boundary_volume.h), so a dam-break column settles standing and
    // is released at t = 0 instead of collapsing while it settles. The settled packing and the
    // multipliers or pressures the solver keeps per particle (its warm start) carry over (dfsph's
    // settle sets only its warm start, dfsph_solver.cpp).
    const Scene gated = gatedScene(scene_);
    const auto gate_solver = makeFluidSolver(gated);
    gate_solver->settle({gated, particles_, grid_, 0.0, gated.params.time_step, false, timings_, solver_stats_});
  }
  timings_ = PhaseTimings{};
}

void Simulation::configureGrid(bool both_classes) {
  const auto classes = scene_.params.classes();
  const double support =
      both_classes ? std::max(classes[0].support, classes[1].support) : classes[classIndex(start_class_)].support;
  grid_.configure(scene_.boundary.enclosingBox(), static_cast<float>(support), particles_.capacity());
}

void Simulation::setAdaptiveStep(std::unique_ptr<AdaptiveStep> step) {
  adaptive_ = std::move(step);
  configureGrid(adaptive_ != nullptr);
}

void Simulation::restore(ParticleSet&& particles, std::int64_t steps, bool surface_distance_tracking) {
  particles_ = std::move(particles);
  steps_ = steps;
  track_surface_distance_ = surface_distance_tracking;
  time_ = static_cast<double>(steps_) * scene_.params.time_step;
}

void Simulation::step() {
  const auto step_start = Clock::now();
  timings_ = PhaseTimings{};

  if (steps_ % scene_.params.resort_interval == 0) {
    // Reorder the arrays into grid-cell order so that neighbours sit close in memory.
    const auto t = Clock::now();
    grid_.bin(particles_);
    particles_.permute(grid_.cellOrder());
    timings_.neighbor_ms += msSince(t);
  }
  solver_->advance(
      {scene_, particles_, grid_, time_, scene_.params.time_step, track_surface_distance_, timings_, solver_stats_});
  // pbf keeps a placed particle's flag until its density constraint holds (pbf_solver.cpp); dfsph
  // reads it only in the frame after the placement (local_placement.h), the thesis's solver never.
  if (scene_.params.solver != Solver::kPbf)
    std::fill(particles_.placed.begin(), particles_.placed.end(), std::uint8_t{0});

  ++steps_;
  time_ = static_cast<double>(steps_) * scene_.params.time_step;  // no drift from repeated sums

  if (adaptive_) {
    const auto t = Clock::now();
    adaptive_->apply(*this);
    timings_.adaptive_ms = msSince(t);
  }
  timings_.total_ms = msSince(step_start);
}

}  // namespace sph
