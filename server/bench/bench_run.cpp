#include "bench/bench_run.h"

#include "bench/gaze_replay.h"
#include "sph/camera.h"

#include <algorithm>
#include <cmath>
#include <omp.h>
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

void measureState(const sph::Simulation& sim, FrameRecord& r) {
  const sph::ParticleSet& p = sim.particles();
  const sph::BoxState box = sim.boxNow();
  const double rho0 = sim.params().rest_density;
  r.n_large = 0;
  r.n_small = 0;
  r.nan_values = 0;
  r.outside_box = 0;
  double density_sum = 0.0;
  double density_max = 0.0;
  // A particle counts as outside when its centre has left the box (a float hair of slack).
  const float slack = 1e-4f;
  for (std::size_t i = 0; i < p.size(); ++i) {
    (p.size_class[i] == sph::SizeClass::Large ? r.n_large : r.n_small) += 1;
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
  }
  const double n = std::max<std::size_t>(p.size(), 1);
  r.mean_density_ratio = density_sum / n / rho0;
  r.max_density_ratio = density_max / rho0;
  r.mean_neighbors = sim.grid().meanNeighbors();
}

RunResult runScene(const sph::Scene& scene, const std::string& method, const RunOptions& options) {
  requireKnownMethod(method);
  if (options.threads < 1) throw std::invalid_argument("threads must be >= 1");
  omp_set_num_threads(options.threads);

  sph::Method m = sph::Method::Regular;
  sph::methodByName(method, m);
  const bool needs_gaze = sph::usesGaze(m);
  if (needs_gaze && (options.gaze == nullptr || options.gaze->samples.empty())) {
    throw std::invalid_argument("method '" + method + "' needs a gaze recording (scene '" +
                                scene.name + "' names none; pass --gaze FILE)");
  }
  sph::Simulation sim(scene, sph::startClass(m));
  auto adaptive = sph::makeAdaptiveController(m, scene.adaptive, sph::cameraFromSpec(scene.camera));
  sph::AdaptiveController* controller = adaptive.get();
  sim.setAdaptiveStep(std::move(adaptive));
  RunResult result;
  result.scene = scene.name;
  result.method = method;
  result.preset = scene.params.preset;
  result.frames = options.frames > 0 ? options.frames : scene.frames;
  result.threads = options.threads;
  result.mass_start = sim.particles().totalMass();
  result.records.reserve(result.frames);
  for (int f = 0; f < result.frames; ++f) {
    if (controller && needs_gaze) controller->setGaze(gazeInputAt(*options.gaze, sim.time()));
    sim.step();
    FrameRecord r;
    if (controller) {
      r.splits = controller->lastStats().splits;
      r.merges = controller->lastStats().merges;
      r.gaze_mode = controller->lastStats().gaze_mode;
    }
    r.frame = f + 1;
    r.sim_time = sim.time();
    r.ms = sim.lastTimings();
    measureState(sim, r);
    result.records.push_back(r);
    if (options.on_frame) options.on_frame(sim, result.records.back());
  }
  result.mass_end = sim.particles().totalMass();
  result.neighbor_stride = sim.grid().stride();
  return result;
}

}  // namespace bench
