#include "sph/simulation.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "sph/fill_water.h"
#include "sph/phase_timer.h"
#include "sph/solvers/fluid_solver_factory.h"

namespace sph {

Simulation::Simulation(const Scene& scene, Level start_class, std::size_t capacity)
    : scene_(scene), particles_(capacity), start_class_(start_class) {
  scene_.params.validate();
  solver_ = makeFluidSolver(scene_);
  start_class_ = fillingLevel(scene_, start_class, *solver_);
  fillWater(scene_, start_class_, *solver_, particles_);
  configureGrid();
  solver_->settleFreshWater({scene_, particles_, grid_, 0.0, scene_.params.time_step, false, timings_, solver_stats_});
  timings_ = PhaseTimings{};
}

void Simulation::configureGrid() {
  const auto classes = scene_.params.levelProps();
  double support = classes[levelIndex(start_class_)].support;
  if (adaptive_ != nullptr) {
    for (int k = 0; k <= levelIndex(adaptive_->coarsest()); ++k) support = std::max(support, classes[k].support);
  }
  grid_.configure(scene_.boundary.enclosingBox(), static_cast<float>(support), particles_.capacity());
}

void Simulation::setAdaptiveStep(std::unique_ptr<AdaptiveStep> step) {
  if (step != nullptr && levelIndex(step->coarsest()) >= scene_.params.levels) {
    throw std::invalid_argument("the method needs " + std::to_string(levelIndex(step->coarsest()) + 1) +
                                " size levels; parameter 'levels' is " + std::to_string(scene_.params.levels));
  }
  if (step != nullptr && levelIndex(step->coarsest()) >= solver_->sizeLevels()) {
    throw std::invalid_argument("the '" + scene_.params.solver + "' solver handles " +
                                std::to_string(solver_->sizeLevels()) +
                                " size levels; this method needs more (use the pbf or dfsph preset)");
  }
  adaptive_ = std::move(step);
  configureGrid();
}

void Simulation::restore(ParticleSet&& particles, std::int64_t steps, bool surface_distance_tracking) {
  particles_ = std::move(particles);
  steps_ = steps;
  track_surface_distance_ = surface_distance_tracking;
  time_ = static_cast<double>(steps_) * scene_.params.time_step;
}

void Simulation::step() {
  timings_ = PhaseTimings{};
  PhaseTimer whole_step(timings_.total_ms);

  if (steps_ % scene_.params.resort_interval == 0) {
    // Reorder the arrays into grid-cell order so that neighbours sit close in memory.
    const PhaseTimer resort(timings_.neighbor_ms);
    grid_.bin(particles_);
    particles_.permute(grid_.cellOrder());
  }
  solver_->advance(
      {scene_, particles_, grid_, time_, scene_.params.time_step, track_surface_distance_, timings_, solver_stats_});
  solver_->releasePlaced(particles_);

  ++steps_;
  time_ = static_cast<double>(steps_) * scene_.params.time_step;  // no drift from repeated sums

  if (adaptive_) {
    const PhaseTimer adaptive(timings_.adaptive_ms);
    adaptive_->apply(*this);
  }
}

}  // namespace sph
