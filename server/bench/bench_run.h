// One headless run of a scene with a method: steps the simulation, records per-frame timings and
// counts, and the health checks (mass, NaN, particles outside the box, density, neighbours).
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bench/machine_load.h"
#include "bench/water_level.h"
#include "gaze/gaze_recording.h"
#include "sph/adaptive/adaptive_controller.h"
#include "sph/scene.h"
#include "sph/simulation.h"

namespace bench {

struct FrameRecord {
  int frame = 0;
  double sim_time = 0.0;
  int levels = sph::kMinLevels;                         // the run's level count (SimParams::levels)
  std::array<std::size_t, sph::kMaxLevels> by_level{};  // particles per level, L0 first
  std::size_t particles() const;
  sph::PhaseTimings ms;
  double mean_neighbors = 0.0;
  double mean_density_ratio = 0.0;  // mean rho / rho0
  double max_density_ratio = 0.0;
  double rms_speed = 0.0;  // m/s
  double volume = 0.0;     // sum of m / rho, m^3
  int substeps = 1;        // solver steps in the frame (SolverStats)
  int solver_iterations = 0;
  int divergence_iterations = 0;
  int placement_iterations = 0;
  std::size_t nan_values = 0;
  std::size_t outside_box = 0;
  int splits = 0;  // adaptive step of this frame
  int merges = 0;
  int merge_unpaired = 0;  // particles flagged MERGE that found no partner
  int split_passes = 0;    // the adaptive step's decisions (AdaptiveStats::split_passes); 0: none
  sph::HeldFiner held;     // foveated: particles finer than the coarsest level a rule keeps from merging
  sph::GazeMode gaze_mode = sph::GazeMode::None;
  // foveated: what the eye gets (adaptive/perceptual_budget.h): visible particles, those wider
  // than the eye's acuity at their eccentricity allows, and the particle under the gaze.
  int visible = 0;
  int over_budget = 0;
  int fovea_level = -1;  // -1: the gaze falls on no water
  double fovea_width_arcmin = 0.0;
  double fovea_mar_arcmin = 0.0;
  // Gazed methods: how far the gaze moved since the frame before, degrees of the display as the
  // user sees it (display_geometry.h); -1 where either frame has no gaze.
  double gaze_jump_deg = -1.0;
};

struct RunResult {
  std::string scene;
  std::string method;
  std::string preset;
  int frames = 0;              // asked; framesRun() were run (fewer when the bench was interrupted)
  double frame_seconds = 0.0;  // simulated time a frame advances (the scene's time_step)
  int threads = 0;
  std::string omp_wait;             // process::ompWaitDescription()
  std::size_t neighbor_stride = 0;  // most entries one neighbour list may hold, at the end
  double mass_start = 0.0;
  double mass_end = 0.0;
  // Other processes and the hypervisor between the run's start and result(): for runs that take
  // turns (sph_bench --interleave), the window of the whole scene.
  MachineLoad machine_load;
  std::vector<FrameRecord> records;  // one a frame run: every figure of the summary is over these
  int framesRun() const { return static_cast<int>(records.size()); }
  bool interrupted() const { return framesRun() < frames; }
  // At the last frame: the water's volume as m / rho0 (m^3; as sum m / rho it is the last record's
  // `volume`), and its level (water_level.h).
  double incompressible_volume = 0.0;
  WaterLevel water_level;
};

struct RunOptions {
  int frames = 0;  // 0: the scene's own count
  int threads = 2;
  // Drives gaze and hybrid; required for them (runScene throws without one).
  const gaze::GazeRecording* gaze = nullptr;
  // Checkpoints (sph/checkpoint.h): start from this one instead of the scene's initial state, and
  // write one when the run has done its frames. Empty: neither.
  std::string load_state;
  std::string save_state;
  // Called after every frame (progress, snapshots); may be empty.
  std::function<void(const sph::Simulation&, const FrameRecord&)> on_frame;
};

// Methods this build knows (sph::methodNames); `regular` is all L0 with no adaptive step.
const std::vector<std::string>& knownMethods();
// Throws std::invalid_argument naming the known methods when `method` is not one of them.
void requireKnownMethod(const std::string& method);
// True for a known method that needs a gaze recording (sph::usesGaze).
bool methodNeedsGaze(const std::string& method);

// One run in progress, advanced a frame at a time, so that several runs can take turns in one
// process (sph_bench --interleave) and see the same machine load. The scene's method settings
// (scene.adaptive) apply; gaze and hybrid need options.gaze (the constructor throws without one).
class SceneRun {
 public:
  SceneRun(const sph::Scene& scene, const std::string& method, const RunOptions& options);
  bool done() const { return static_cast<int>(result_.records.size()) >= result_.frames; }
  // Steps one frame, records it and calls options.on_frame. Sets OpenMP's thread count first
  // (another run may have changed it).
  void stepFrame();
  // The result so far, with the end-of-run fields (mass at the end, neighbour stride) filled in.
  RunResult result() const;
  // The simulation as the last frame left it (benchmarks start from a run's state).
  const sph::Simulation& simulation() const { return *sim_; }

 private:
  RunOptions options_;
  bool needs_gaze_ = false;
  std::unique_ptr<sph::Simulation> sim_;
  sph::AdaptiveController* controller_ = nullptr;
  // The display as the user sees it (display_geometry.h), and the last frame's gaze direction.
  float display_tan_half_ = 1.0f;
  float display_aspect_ = 1.0f;
  bool had_gaze_ = false;
  Eigen::Vector3f last_gaze_ = Eigen::Vector3f::UnitZ();
  RunResult result_;
  CpuSnapshot start_;
};

// A whole run, start to end.
RunResult runScene(const sph::Scene& scene, const std::string& method, const RunOptions& options);

// Health of the particle set at the current instant (used per frame and by tests).
void measureState(const sph::Simulation& sim, FrameRecord& record);

}  // namespace bench
