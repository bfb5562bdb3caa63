// Writes a run's summary.json and frames.csv, and particle snapshots (CSV or legacy VTK).
#pragma once

#include <array>
#include <string>

#include "bench/bench_run.h"
#include "sph/particles.h"

namespace bench {

struct PhaseStats {
  double mean = 0.0;
  double p95 = 0.0;
};

// A saccade (Summary): the gaze moving more than this in a frame, degrees: at 10 ms frames 200
// degrees a second, which only a saccade reaches (smooth pursuit stays under about 100).
inline constexpr double kSaccadeDeg = 2.0;
// The frames within which the gaze point should be at L0 after a saccade, the saccade's own
// frame the first (as Foveated.ANewFoveaIsAtItsLevelsWithinThreeFrames and BasinFovea check one
// saccade each).
inline constexpr int kSaccadeFrames = 3;

struct Summary {
  PhaseStats neighbor, density_pressure, accel_integrate_collide, adaptive, total;
  double steps_per_s = 0.0;
  // The steps' wall-clock seconds per simulated second (the simulation's own cost; the bench's
  // measurements between steps left out): under 1 is faster than real time.
  double wall_per_simulated = 0.0;
  int levels = sph::kMinLevels;                       // the run's level count
  std::array<double, sph::kMaxLevels> mean_levels{};  // mean particles per level, L0 first
  double mean_neighbors = 0.0;
  // foveated: the largest and the mean share of visible particles over the perceptual budget in a
  // frame, and of the frames where the gaze fell on water, the share that found the finest level
  // there, with the mean angular width of that particle and the eye's MAR there (arcmin).
  double max_over_budget_share = 0.0;
  double mean_over_budget_share = 0.0;
  bool budget_measured = false;  // some frame counted visible particles (foveated)
  int gaze_on_water_frames = 0;
  double gaze_finest_share = 0.0;
  double mean_fovea_width_arcmin = 0.0;
  double mean_fovea_mar_arcmin = 0.0;
  // Gazed methods: the saccades (the gaze jumping more than kSaccadeDeg in a frame, the next
  // jump more than kSaccadeFrames frames later) after which the gaze falls on water in the
  // kSaccadeFrames-th frame, those of them whose particle under the gaze is at L0 there, and the
  // most frames any of them took to reach L0 (counting the saccade's; 0: none).
  int saccades_on_water = 0;
  int saccades_finest_in_time = 0;
  int saccade_most_frames_to_finest = 0;
  // foveated: the mean a frame of the particles finer than the coarsest level that a rule keeps
  // from merging (FrameRecord::held).
  double mean_held_by_eye = 0.0, mean_held_by_grading = 0.0, mean_held_by_thin = 0.0, mean_held_waiting = 0.0;
  double mean_density_ratio = 0.0, max_density_ratio = 0.0;
  std::size_t nan_values = 0, outside_box = 0;
};

Summary summarize(const RunResult& run);
void writeSummaryJson(const RunResult& run, const Summary& s, const std::string& path);
void writeFramesCsv(const RunResult& run, const std::string& path);
// The water's volume and level at the last frame, in words (water_level.h).
std::string describeVolume(const RunResult& run);
// One line for the terminal.
std::string summaryText(const RunResult& run, const Summary& s);
// "900 frames", or for a run stopped early "30 of 3000 frames (INTERRUPTED)".
std::string framesText(const RunResult& run);

// Vtu: binary VTK XML with a .pvd time index (vtu_export.h); Vtk: legacy ASCII; Csv: one row a particle.
enum class SnapshotFormat { Csv, Vtk, Vtu };
void writeSnapshot(const sph::ParticleSet& particles, SnapshotFormat format, const std::string& path);

}  // namespace bench
