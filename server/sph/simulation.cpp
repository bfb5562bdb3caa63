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
    : scene_(scene), kernels_(makeKernelTable(scene.params)), particles_(capacity) {
  scene_.params.validate();
  fillWater(scene_, start_class, particles_);
  const auto classes = scene_.params.classes();
  const double max_support = std::max(classes[0].support, classes[1].support);
  grid_.configure(scene_.boundary.enclosingBox(), static_cast<float>(max_support), capacity);
}

void Simulation::step() {
  const auto step_start = Clock::now();

  auto t = Clock::now();
  if (steps_ % scene_.params.resort_interval == 0) {
    // Reorder the arrays into grid-cell order so that neighbours sit close in memory.
    grid_.bin(particles_);
    particles_.permute(grid_.cellOrder());
  }
  grid_.build(particles_);
  timings_.neighbor_ms = msSince(t);

  t = Clock::now();
  computeDensityPressure(scene_.params, kernels_, grid_, particles_);
  timings_.density_pressure_ms = msSince(t);

  t = Clock::now();
  computeAccelerations(scene_.params, kernels_, grid_, particles_, track_surface_distance_);
  const double next_time = time_ + scene_.params.time_step;
  integrateAndCollide(scene_.params, scene_.boundary, scene_.boundary.stateAt(next_time), particles_);
  timings_.accel_integrate_collide_ms = msSince(t);

  ++steps_;
  time_ = static_cast<double>(steps_) * scene_.params.time_step;  // no drift from repeated sums

  timings_.adaptive_ms = 0.0;
  if (adaptive_) {
    t = Clock::now();
    adaptive_->apply(*this);
    timings_.adaptive_ms = msSince(t);
  }
  timings_.total_ms = msSince(step_start);
}

}  // namespace sph
