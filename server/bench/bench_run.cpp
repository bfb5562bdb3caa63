#include "bench/bench_run.h"

#include "bench/gaze_replay.h"
#include "process/omp_wait.h"
#include "sph/adaptive/display_geometry.h"
#include "sph/camera.h"
#include "sph/checkpoint.h"

#include <omp.h>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bench {

const std::vector<std::string>& knownMethods() {
  static const std::vector<std::string> methods = sph::methodNames();
  return methods;
}

void requireKnownMethod(const std::string& method) {
  const auto& known = knownMethods();
  if (std::find(known.begin(), known.end(), method) != known.end()) return;
  std::string list;
  for (const auto& m : known) list += (list.empty() ? "" : ", ") + m;
  throw std::invalid_argument("unknown method '" + method + "' (known: " + list + ")");
}

bool methodNeedsGaze(const std::string& method) {
  sph::Method m;
  return sph::methodByName(method, m) && sph::usesGaze(m);
}

std::size_t FrameRecord::particles() const {
  std::size_t n = 0;
  for (const std::size_t c : by_level) n += c;
  return n;
}

void measureState(const sph::Simulation& sim, FrameRecord& r) {
  const sph::ParticleSet& p = sim.particles();
  const sph::BoxState box = sim.boxNow();
  const double rho0 = sim.params().rest_density;
  r.levels = sim.params().levels;
  r.by_level = {};
  r.nan_values = 0;
  r.outside_box = 0;
  double density_sum = 0.0;
  double density_max = 0.0;
  double speed_sq_sum = 0.0;
  double volume = 0.0;
  // A particle counts as outside when its centre has left the box (a float hair of slack).
  const float slack = 1e-4f;
  for (std::size_t i = 0; i < p.size(); ++i) {
    r.by_level[static_cast<std::size_t>(sph::levelIndex(p.level[i]))] += 1;
    const sph::Vec3& x = p.position[i];
    const sph::Vec3& u = p.velocity[i];
    for (int a = 0; a < 3; ++a) {
      r.nan_values += !std::isfinite(x[a]) + !std::isfinite(u[a]);
    }
    r.nan_values += !std::isfinite(p.density[i]);
    if ((x.array() < box.min.array() - slack).any() || (x.array() > box.max.array() + slack).any()) {
      ++r.outside_box;
    }
    density_sum += p.density[i];
    density_max = std::max(density_max, static_cast<double>(p.density[i]));
    speed_sq_sum += u.squaredNorm();
    volume += p.density[i] > 0.0f ? p.mass[i] / p.density[i] : 0.0;
  }
  const double n = std::max<std::size_t>(p.size(), 1);
  r.mean_density_ratio = density_sum / n / rho0;
  r.max_density_ratio = density_max / rho0;
  r.rms_speed = std::sqrt(speed_sq_sum / n);
  r.volume = volume;
  r.mean_neighbors = sim.grid().meanNeighbors();
  const sph::SolverStats& solver = sim.lastSolverStats();
  r.substeps = solver.substeps;
  r.solver_iterations = solver.iterations;
  r.divergence_iterations = solver.divergence_iterations;
  r.placement_iterations = solver.placement_iterations;
}

SceneRun::SceneRun(const sph::Scene& scene, const std::string& method, const RunOptions& options) : options_(options) {
  requireKnownMethod(method);
  if (options.threads < 1) throw std::invalid_argument("threads must be >= 1");
  omp_set_num_threads(options.threads);

  sph::Method m = sph::Method::Regular;
  sph::methodByName(method, m);
  needs_gaze_ = sph::usesGaze(m);
  if (needs_gaze_ && (options.gaze == nullptr || options.gaze->samples.empty())) {
    throw std::invalid_argument("method '" + method + "' needs a gaze recording (scene '" + scene.name +
                                "' names none; pass --gaze FILE)");
  }
  // Room for every particle to split to L0, as sph_server allows (app/sim_session.cpp).
  const std::size_t capacity = sph::refinedCapacity(scene);
  sim_ = std::make_unique<sph::Simulation>(scene, sph::startLevel(m, scene.params.levels), capacity);
  const sph::ScreenCamera camera = sph::cameraFromSpec(scene.camera);
  auto adaptive = sph::makeAdaptiveController(m, scene.params.levels, scene.adaptive, camera);
  controller_ = adaptive.get();
  display_tan_half_ = sph::displayTanHalf(scene.adaptive, camera);
  display_aspect_ = static_cast<float>(sph::Projector(camera).aspect());
  // The perceptual meter is the bench's instrument, not the method's cost: it runs after the
  // timed step (stepFrame), on the same particles.
  if (controller_ != nullptr) controller_->setMeasureEachStep(false);
  sim_->setAdaptiveStep(std::move(adaptive));
  if (!options.load_state.empty()) sph::loadCheckpoint(*sim_, method, options.load_state);
  result_.scene = scene.name;
  result_.method = method;
  result_.preset = scene.params.preset;
  result_.frames = options.frames > 0 ? options.frames : scene.frames;
  result_.frame_seconds = scene.params.time_step;
  result_.threads = options.threads;
  result_.omp_wait = process::ompWaitDescription();
  result_.mass_start = sim_->particles().totalMass();
  result_.records.reserve(result_.frames);
  start_ = takeCpuSnapshot();
}

void SceneRun::stepFrame() {
  omp_set_num_threads(options_.threads);
  FrameRecord r;
  if (controller_ && needs_gaze_) {
    const sph::GazeInput gaze = gazeInputAt(*options_.gaze, sim_->time());
    controller_->setGaze(gaze);
    const Eigen::Vector3f direction = sph::screenDirection(static_cast<float>(gaze.x), static_cast<float>(gaze.y),
                                                           display_tan_half_, display_aspect_);
    if (gaze.present && had_gaze_) r.gaze_jump_deg = sph::angleDeg(direction, last_gaze_);
    had_gaze_ = gaze.present;
    last_gaze_ = direction;
  }
  sim_->step();
  if (controller_) {
    controller_->measureEye(*sim_);
    r.splits = controller_->lastStats().splits;
    r.merges = controller_->lastStats().merges;
    r.merge_unpaired = controller_->lastStats().merge_wanted - 2 * r.merges;
    r.split_passes = controller_->lastStats().split_passes;
    r.held = controller_->lastStats().held;
    r.gaze_mode = controller_->lastStats().gaze_mode;
    r.visible = controller_->lastStats().visible;
    r.over_budget = controller_->lastStats().over_budget;
    r.fovea_level = controller_->lastStats().fovea_level;
    r.fovea_width_arcmin = controller_->lastStats().fovea_width_arcmin;
    r.fovea_mar_arcmin = controller_->lastStats().fovea_mar_arcmin;
  }
  r.frame = static_cast<int>(result_.records.size()) + 1;
  r.sim_time = sim_->time();
  r.ms = sim_->lastTimings();
  measureState(*sim_, r);
  result_.records.push_back(r);
  if (done() && !options_.save_state.empty()) sph::saveCheckpoint(*sim_, result_.method, options_.save_state);
  if (options_.on_frame) options_.on_frame(*sim_, result_.records.back());
}

RunResult SceneRun::result() const {
  RunResult out = result_;
  out.mass_end = sim_->particles().totalMass();
  out.neighbor_stride = sim_->grid().stride();
  out.machine_load = loadBetween(start_, takeCpuSnapshot());
  const double rho0 = sim_->params().rest_density;
  out.incompressible_volume = out.mass_end / rho0;
  out.water_level = measureWaterLevel(sim_->particles(), sim_->scene(), sim_->boxNow());
  return out;
}

RunResult runScene(const sph::Scene& scene, const std::string& method, const RunOptions& options) {
  SceneRun run(scene, method, options);
  while (!run.done()) run.stepFrame();
  return run.result();
}

}  // namespace bench
