// sph_gaze_record: writes the synthetic gaze recording a scene ships with (scenes/<name>.gaze.csv),
// so that headless runs of the gaze and hybrid methods are reproducible. Fixation targets are points
// on the water at the time of the fixation: the tool first runs the scene (L1 particles, no
// adaptive step) and keeps the projected positions of a sample of particles every 0.1 s; a target
// is one of them, as a viewer's eye jumps between places on the water. The seed comes from the
// scene name and the simulation is deterministic, so a recording is remade bit for bit.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <utility>
#include <vector>

#include "cli/cli_conventions.h"
#include "gaze/fixation_model.h"
#include "gaze/gaze_recording.h"
#include "scene/scene_loader.h"
#include "sph/camera.h"
#include "sph/simulation.h"

namespace {

// FNV-1a: a stable seed per scene name.
std::uint64_t seedOf(const std::string& name) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : name) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}

// Screen rectangle (normalized, origin top left) covering the region the water occupies over the
// run, shrunk a little: the model's fallback when a snapshot has no visible water.
void waterOnScreen(const sph::Scene& scene, gaze::FixationModelParams& params) {
  const sph::Aabb box = scene.boundary.enclosingBox();
  sph::Aabb wet = box;
  wet.max.y() = scene.water.max.y();
  const sph::Projector projector(sph::cameraFromSpec(scene.camera));
  double x0 = 1.0, y0 = 1.0, x1 = 0.0, y1 = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p((corner & 1) ? wet.max.x() : wet.min.x(), (corner & 2) ? wet.max.y() : wet.min.y(),
                            (corner & 4) ? wet.max.z() : wet.min.z());
    const sph::ScreenDisc d = projector.project(p, 0.0);
    if (!d.in_front) continue;
    x0 = std::min(x0, d.x);
    y0 = std::min(y0, d.y);
    x1 = std::max(x1, d.x);
    y1 = std::max(y1, d.y);
  }
  const auto clamp = [](double v) { return std::clamp(v, 0.05, 0.95); };
  const double mx = 0.1 * (x1 - x0);
  const double my = 0.1 * (y1 - y0);
  params.region_x0 = clamp(x0 + mx);
  params.region_x1 = clamp(x1 - mx);
  params.region_y0 = clamp(y0 + my);
  params.region_y1 = clamp(y1 - my);
  if (params.region_x1 <= params.region_x0 || params.region_y1 <= params.region_y0) {
    throw std::invalid_argument("scene '" + scene.name + "': the water is not in the camera's view");
  }
}

// Projected positions (normalized screen, in front of the eye) of up to `per_snapshot` particles,
// every `interval_s` of simulated time over the scene's run.
class WaterOnScreen {
 public:
  WaterOnScreen(const sph::Scene& scene, double interval_s, std::size_t per_snapshot) : interval_s_(interval_s) {
    sph::Simulation sim(scene, sph::Level{1}, sph::refinedCapacity(scene));
    const sph::Projector projector(sph::cameraFromSpec(scene.camera));
    const int steps_per_snapshot = std::max(1, static_cast<int>(std::lround(interval_s / scene.params.time_step)));
    for (int step = 0; step <= scene.frames; ++step) {
      if (step % steps_per_snapshot == 0) {
        std::vector<std::pair<double, double>> points;
        const std::size_t n = sim.particles().size();
        const std::size_t stride = std::max<std::size_t>(1, n / per_snapshot);
        for (std::size_t i = 0; i < n; i += stride) {
          const sph::ScreenDisc d = projector.project(sim.particles().position[i].cast<double>(), 0.0);
          if (d.in_front && d.x >= 0.0 && d.x <= 1.0 && d.y >= 0.0 && d.y <= 1.0) {
            points.emplace_back(d.x, d.y);
          }
        }
        snapshots_.push_back(std::move(points));
      }
      if (step < scene.frames) sim.step();
    }
  }

  bool pick(double time_s, double u, double& x, double& y) const {
    if (snapshots_.empty()) return false;
    const auto k =
        std::min<std::size_t>(snapshots_.size() - 1, static_cast<std::size_t>(std::max(0.0, time_s) / interval_s_));
    const auto& points = snapshots_[k];
    if (points.empty()) return false;
    const auto& p = points[std::min(points.size() - 1, static_cast<std::size_t>(u * points.size()))];
    x = p.first;
    y = p.second;
    return true;
  }

 private:
  double interval_s_;
  std::vector<std::vector<std::pair<double, double>>> snapshots_;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"sph_gaze_record: write a scene's synthetic gaze recording (fixations and saccades)"};
  cli::prepare(app, "sph_gaze_record");
  std::string scene_arg = "all";
  std::string scene_dir = scene::defaultSceneDir();
  std::string out_dir;
  double rate_hz = 120.0;
  double blink_probability = 0.1;
  app.add_option("--scene", scene_arg, "scene name, path, or 'all'")->capture_default_str();
  app.add_option("--scene-dir", scene_dir, "folder of named scenes")->capture_default_str();
  app.add_option("--out-dir", out_dir, "where <scene>.gaze.csv goes (default: the scene folder)");
  app.add_option("--rate", rate_hz, "samples per second")->check(cli::range(1, 2000))->capture_default_str();
  app.add_option("--blink-probability", blink_probability, "chance per fixation of a 0.1 s gap")
      ->check(cli::range(0, 1))
      ->capture_default_str();
  if (auto code = cli::parse(app, argc, argv)) return *code;
  try {
    const std::vector<std::string> names =
        scene_arg == "all" ? scene::listScenes(scene_dir) : std::vector<std::string>{scene_arg};
    for (const std::string& name : names) {
      const sph::Scene sc = scene::loadScene(name, scene_dir);
      gaze::FixationModelParams params;
      params.seed = seedOf(sc.name);
      params.rate_hz = rate_hz;
      params.blink_probability = blink_probability;
      waterOnScreen(sc, params);
      const WaterOnScreen water(sc, 0.1, 2000);
      params.pick_target = [&water](double t, double u, double& x, double& y) { return water.pick(t, u, x, y); };
      // The whole run plus a second, so the recording covers it without looping.
      const double seconds = sc.frames * sc.params.time_step + 1.0;
      const gaze::GazeRecording rec = gaze::synthesizeRecording(params, seconds);
      const std::filesystem::path dir(out_dir.empty() ? scene_dir : out_dir);
      const std::filesystem::path path = dir / (sc.name + ".gaze.csv");
      gaze::writeGazeRecording(path.string(), rec);
      std::printf("%s: %zu samples, %.1f s, targets in x [%.3f, %.3f] y [%.3f, %.3f] -> %s\n", sc.name.c_str(),
                  rec.samples.size(), rec.duration(), params.region_x0, params.region_x1, params.region_y0,
                  params.region_y1, path.string().c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sph_gaze_record: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
