#include "bench/bench_output.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

namespace bench {

namespace {

PhaseStats stats(const RunResult& run, double sph::PhaseTimings::*field) {
  PhaseStats s;
  if (run.records.empty()) return s;
  std::vector<double> v;
  v.reserve(run.records.size());
  for (const FrameRecord& r : run.records) v.push_back(r.ms.*field);
  double sum = 0.0;
  for (double x : v) sum += x;
  s.mean = sum / static_cast<double>(v.size());
  std::sort(v.begin(), v.end());
  s.p95 = v[std::min(v.size() - 1, static_cast<std::size_t>(0.95 * static_cast<double>(v.size())))];
  return s;
}

std::ofstream openOut(const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write '" + path + "'");
  return out;
}

nlohmann::json phaseJson(const PhaseStats& p) { return {{"mean_ms", p.mean}, {"p95_ms", p.p95}}; }

// sum m / rho at the last frame (the frames' volume column).
double volumeAtEnd(const RunResult& run) { return run.records.empty() ? 0.0 : run.records.back().volume; }

}  // namespace

// Summary's saccade counts: each saccade not followed by another within kSaccadeFrames frames,
// judged at its kSaccadeFrames-th frame where the gaze falls on water there.
static void countSaccades(const RunResult& run, Summary& s) {
  const auto& records = run.records;
  const auto jumps = [&](std::size_t f) { return records[f].gaze_jump_deg > kSaccadeDeg; };
  for (std::size_t f = 0; f + kSaccadeFrames <= records.size(); ++f) {
    if (!jumps(f)) continue;
    const std::size_t judged = f + kSaccadeFrames - 1;
    bool superseded = false;
    for (std::size_t g = f + 1; g <= judged; ++g) superseded = superseded || jumps(g);
    if (superseded || records[judged].fovea_level < 0) continue;
    ++s.saccades_on_water;
    s.saccades_finest_in_time += records[judged].fovea_level == 0;
    // Frames to L0, counting the saccade's: on to the next saccade at most.
    for (std::size_t g = f; g < records.size() && (g == f || !jumps(g)); ++g) {
      if (records[g].fovea_level == 0) {
        s.saccade_most_frames_to_finest = std::max(s.saccade_most_frames_to_finest, static_cast<int>(g - f + 1));
        break;
      }
    }
  }
}

Summary summarize(const RunResult& run) {
  Summary s;
  s.neighbor = stats(run, &sph::PhaseTimings::neighbor_ms);
  s.density_pressure = stats(run, &sph::PhaseTimings::density_pressure_ms);
  s.accel_integrate_collide = stats(run, &sph::PhaseTimings::accel_integrate_collide_ms);
  s.adaptive = stats(run, &sph::PhaseTimings::adaptive_ms);
  s.total = stats(run, &sph::PhaseTimings::total_ms);
  s.steps_per_s = s.total.mean > 0.0 ? 1000.0 / s.total.mean : 0.0;
  s.wall_per_simulated = run.frame_seconds > 0.0 ? s.total.mean / 1000.0 / run.frame_seconds : 0.0;
  const double n = std::max<std::size_t>(run.records.size(), 1);
  for (const FrameRecord& r : run.records) {
    s.levels = r.levels;
    for (std::size_t k = 0; k < r.by_level.size(); ++k) s.mean_levels[k] += static_cast<double>(r.by_level[k]) / n;
    if (r.visible > 0) {
      s.budget_measured = true;
      const double share = static_cast<double>(r.over_budget) / r.visible;
      s.max_over_budget_share = std::max(s.max_over_budget_share, share);
      s.mean_over_budget_share += share / n;
    }
    if (r.fovea_level >= 0) {
      ++s.gaze_on_water_frames;
      s.gaze_finest_share += r.fovea_level == 0;
      s.mean_fovea_width_arcmin += r.fovea_width_arcmin;
      s.mean_fovea_mar_arcmin += r.fovea_mar_arcmin;
    }
    s.mean_held_by_eye += r.held.eye / n;
    s.mean_held_by_grading += r.held.grading / n;
    s.mean_held_by_thin += r.held.thin / n;
    s.mean_held_waiting += r.held.waiting / n;
    s.mean_neighbors += r.mean_neighbors / n;
    s.mean_density_ratio += r.mean_density_ratio / n;
    s.max_density_ratio = std::max(s.max_density_ratio, r.max_density_ratio);
    s.nan_values += r.nan_values;
    s.outside_box += r.outside_box;
  }
  countSaccades(run, s);
  if (s.gaze_on_water_frames > 0) {
    s.gaze_finest_share /= s.gaze_on_water_frames;
    s.mean_fovea_width_arcmin /= s.gaze_on_water_frames;
    s.mean_fovea_mar_arcmin /= s.gaze_on_water_frames;
  }
  return s;
}

void writeSummaryJson(const RunResult& run, const Summary& s, const std::string& path) {
  nlohmann::json j;
  j["scene"] = run.scene;
  j["method"] = run.method;
  j["preset"] = run.preset;
  j["frames"] = run.framesRun();  // what the figures are over
  j["frames_asked"] = run.frames;
  j["interrupted"] = run.interrupted();
  j["threads"] = run.threads;
  j["omp_wait"] = run.omp_wait;
  // What else ran on the machine meanwhile (machine_load.h); null where it cannot be read.
  j["machine_load"] = run.machine_load.known ? nlohmann::json{{"other_processes_cores", run.machine_load.other_cores},
                                                              {"stolen_cores", run.machine_load.steal_cores}}
                                             : nlohmann::json();
  j["phases"] = {{"neighbor_search", phaseJson(s.neighbor)},
                 {"density_pressure", phaseJson(s.density_pressure)},
                 {"accel_integrate_collide", phaseJson(s.accel_integrate_collide)},
                 {"adaptive", phaseJson(s.adaptive)},
                 {"total", phaseJson(s.total)}};
  j["steps_per_s"] = s.steps_per_s;
  j["wall_seconds_per_simulated_second"] = s.wall_per_simulated;
  j["mean_levels"] = std::vector<double>(s.mean_levels.begin(), s.mean_levels.begin() + s.levels);
  j["max_over_budget_share"] = s.max_over_budget_share;
  j["mean_over_budget_share"] = s.mean_over_budget_share;
  j["gaze_on_water_frames"] = s.gaze_on_water_frames;
  j["gaze_finest_share"] = s.gaze_finest_share;
  j["mean_fovea_width_arcmin"] = s.mean_fovea_width_arcmin;
  j["mean_fovea_mar_arcmin"] = s.mean_fovea_mar_arcmin;
  j["saccades"] = {{"on_water", s.saccades_on_water},
                   {"finest_within_frames", s.saccades_finest_in_time},
                   {"frames", kSaccadeFrames},
                   {"most_frames_to_finest", s.saccade_most_frames_to_finest}};
  j["mean_held_finer"] = {{"eye", s.mean_held_by_eye},
                          {"grading", s.mean_held_by_grading},
                          {"thin", s.mean_held_by_thin},
                          {"waiting", s.mean_held_waiting}};
  j["mean_neighbors_per_particle"] = s.mean_neighbors;
  j["neighbor_list_stride"] = run.neighbor_stride;
  j["mean_density_over_rho0"] = s.mean_density_ratio;
  j["max_density_over_rho0"] = s.max_density_ratio;
  j["total_mass_start"] = run.mass_start;
  j["total_mass_end"] = run.mass_end;
  j["nan_values"] = s.nan_values;              // summed over all frames
  j["particles_outside_box"] = s.outside_box;  // summed over all frames
  // At the last frame (water_level.h): the volume as sum m / rho against sum m / rho0, and the
  // gauges' mean level against the depth sum m / rho0 fills; null where no gauge fits.
  j["volume_end"] = {{"sum_m_over_rho", volumeAtEnd(run)}, {"sum_m_over_rho0", run.incompressible_volume}};
  // The rms speed then (m/s): whether the level below is a settled depth.
  j["rms_speed_end"] = run.records.empty() ? nlohmann::json() : nlohmann::json(run.records.back().rms_speed);
  const WaterLevel& level = run.water_level;
  j["water_level_end"] = level.gauges > 0 ? nlohmann::json{{"depth", level.depth},
                                                           {"incompressible_depth", level.incompressible_depth},
                                                           {"gauges", level.gauges},
                                                           {"wet_gauges", level.wet}}
                                          : nlohmann::json();
  openOut(path) << j.dump(2) << "\n";
}

// "a b c": the frame's particles per level, L0 first.
static std::string levelCounts(const FrameRecord& r) {
  std::string text;
  for (int k = 0; k < r.levels; ++k) {
    if (k > 0) text += ' ';
    text += std::to_string(r.by_level[static_cast<std::size_t>(k)]);
  }
  return text;
}

void writeFramesCsv(const RunResult& run, const std::string& path) {
  std::ofstream out = openOut(path);
  // `levels`: the particles per level, L0 first, as many as the run has levels, space-separated.
  out << "frame,sim_time,particles,levels,neighbor_ms,density_pressure_ms,accel_integrate_collide_ms,"
         "adaptive_ms,total_ms,steps_per_s,mean_neighbors,mean_density_over_rho0,max_density_over_rho0,"
         "splits,merges,gaze_mode,merge_unpaired,rms_speed,volume,substeps,solver_iterations,"
         "divergence_iterations,placement_iterations,visible,over_budget,fovea_level,fovea_width_arcmin,"
         "fovea_mar_arcmin,split_passes,held_by_eye,held_by_grading,held_by_thin,held_waiting,gaze_jump_deg\n";
  char line[720];
  for (const FrameRecord& r : run.records) {
    const double steps_per_s = r.ms.total_ms > 0.0 ? 1000.0 / r.ms.total_ms : 0.0;
    std::snprintf(line, sizeof line,
                  "%d,%.4f,%zu,%s,%.4f,%.4f,%.4f,%.4f,%.4f,%.2f,%.2f,%.4f,%.4f,%d,%d,%s,%d,%.5f,%.6f,%d,%d,%d,%d,%d,%d,"
                  "%d,%.3f,%.3f,%d,%d,%d,%d,%d,%.3f\n",
                  r.frame, r.sim_time, r.particles(), levelCounts(r).c_str(), r.ms.neighbor_ms,
                  r.ms.density_pressure_ms, r.ms.accel_integrate_collide_ms, r.ms.adaptive_ms, r.ms.total_ms,
                  steps_per_s, r.mean_neighbors, r.mean_density_ratio, r.max_density_ratio, r.splits, r.merges,
                  sph::gazeModeName(r.gaze_mode), r.merge_unpaired, r.rms_speed, r.volume, r.substeps,
                  r.solver_iterations, r.divergence_iterations, r.placement_iterations, r.visible, r.over_budget,
                  r.fovea_level, r.fovea_width_arcmin, r.fovea_mar_arcmin, r.split_passes, r.held.eye, r.held.grading,
                  r.held.thin, r.held.waiting, r.gaze_jump_deg);
    out << line;
  }
}

std::string describeVolume(const RunResult& run) {
  char buf[256];
  const double volume =
      run.incompressible_volume > 0.0 ? 100.0 * (volumeAtEnd(run) / run.incompressible_volume - 1.0) : 0.0;
  const WaterLevel& level = run.water_level;
  if (level.gauges == 0 || level.incompressible_depth <= 0.0) {
    std::snprintf(buf, sizeof buf, "volume (sum m / rho) %+.2f %%, level n/a (no gauge clear of the walls)", volume);
  } else {
    std::snprintf(buf, sizeof buf,
                  "volume (sum m / rho) %+.2f %%, level %.4f m against %.4f m (%+.2f %%, %d of %d gauges wet)", volume,
                  level.depth, level.incompressible_depth, 100.0 * (level.depth / level.incompressible_depth - 1.0),
                  level.wet, level.gauges);
  }
  std::string text = buf;
  // The water's motion then: the level is the settled depth only once the water is at rest (a dam
  // break still sloshes at 9 s, and its level there differs from the settled one).
  if (!run.records.empty()) {
    std::snprintf(buf, sizeof buf, ", rms speed %.3f m/s", run.records.back().rms_speed);
    text += buf;
  }
  return text;
}

std::string framesText(const RunResult& run) {
  if (!run.interrupted()) return std::to_string(run.frames) + " frames";
  return std::to_string(run.framesRun()) + " of " + std::to_string(run.frames) + " frames (INTERRUPTED)";
}

// The mean particles per level, "L0 a, L1 b, ...", and the foveated method's perceptual budget.
static std::string levelText(const Summary& s) {
  std::string text;
  char buf[160];
  for (int k = 0; k < s.levels; ++k) {
    std::snprintf(buf, sizeof buf, "%sL%d %.0f", k == 0 ? "" : ", ", k, s.mean_levels[static_cast<std::size_t>(k)]);
    text += buf;
  }
  if (s.budget_measured) {
    std::snprintf(buf, sizeof buf, " (over budget mean %.2f %%, at most %.2f %%)", 100.0 * s.mean_over_budget_share,
                  100.0 * s.max_over_budget_share);
    text += buf;
  }
  if (s.mean_held_by_eye + s.mean_held_by_grading + s.mean_held_by_thin + s.mean_held_waiting > 0.0) {
    std::snprintf(buf, sizeof buf, " | kept finer by: the eye %.0f, grading %.0f, thin water %.0f, waiting %.0f",
                  s.mean_held_by_eye, s.mean_held_by_grading, s.mean_held_by_thin, s.mean_held_waiting);
    text += buf;
  }
  if (s.gaze_on_water_frames > 0) {
    std::snprintf(buf, sizeof buf, " | under the gaze: L0 in %.0f %% of %d frames, %.1f' wide against MAR %.2f'",
                  100.0 * s.gaze_finest_share, s.gaze_on_water_frames, s.mean_fovea_width_arcmin,
                  s.mean_fovea_mar_arcmin);
    text += buf;
  }
  if (s.saccades_on_water > 0) {
    std::snprintf(buf, sizeof buf, "; after %d saccades L0 by frame %d in %d (at most %d frames)", s.saccades_on_water,
                  kSaccadeFrames, s.saccades_finest_in_time, s.saccade_most_frames_to_finest);
    text += buf;
  }
  return text;
}

std::string summaryText(const RunResult& run, const Summary& s) {
  char buf[2048];
  std::snprintf(buf, sizeof buf,
                "%s/%s (%s): %s, %d threads | mean ms: neighbours %.3f, density+pressure %.3f, "
                "accel+integrate+collide %.3f, adaptive %.3f, total %.3f (p95 %.3f) | %.1f steps/s, "
                "%.2f wall s per simulated s | "
                "%s | neighbours %.1f | rho/rho0 mean %.3f max %.3f | mass %.6f -> %.6f | "
                "NaN %zu, outside %zu | at the end: %s | other load: %s",
                run.scene.c_str(), run.method.c_str(), run.preset.c_str(), framesText(run).c_str(), run.threads,
                s.neighbor.mean, s.density_pressure.mean, s.accel_integrate_collide.mean, s.adaptive.mean, s.total.mean,
                s.total.p95, s.steps_per_s, s.wall_per_simulated, levelText(s).c_str(), s.mean_neighbors,
                s.mean_density_ratio, s.max_density_ratio, run.mass_start, run.mass_end, s.nan_values, s.outside_box,
                describeVolume(run).c_str(), describe(run.machine_load).c_str());
  return buf;
}

void writeSnapshot(const sph::ParticleSet& p, SnapshotFormat format, const std::string& path) {
  std::ofstream out = openOut(path);
  const std::size_t n = p.size();
  if (format == SnapshotFormat::Csv) {
    out << "id,x,y,z,vx,vy,vz,density,pressure,mass,radius,level\n";
    for (std::size_t i = 0; i < n; ++i) {
      const auto& x = p.position[i];
      const auto& u = p.velocity[i];
      out << p.id[i] << ',' << x.x() << ',' << x.y() << ',' << x.z() << ',' << u.x() << ',' << u.y() << ',' << u.z()
          << ',' << p.density[i] << ',' << p.pressure[i] << ',' << p.mass[i] << ',' << p.radius[i] << ','
          << static_cast<int>(p.level[i]) << '\n';
    }
    return;
  }
  // Legacy VTK polydata (ASCII): ParaView opens it directly.
  out << "# vtk DataFile Version 3.0\nsph particles\nASCII\nDATASET POLYDATA\n";
  out << "POINTS " << n << " float\n";
  for (std::size_t i = 0; i < n; ++i) {
    out << p.position[i].x() << ' ' << p.position[i].y() << ' ' << p.position[i].z() << '\n';
  }
  out << "VERTICES " << n << ' ' << 2 * n << '\n';
  for (std::size_t i = 0; i < n; ++i) out << "1 " << i << '\n';
  out << "POINT_DATA " << n << "\nVECTORS velocity float\n";
  for (std::size_t i = 0; i < n; ++i) {
    out << p.velocity[i].x() << ' ' << p.velocity[i].y() << ' ' << p.velocity[i].z() << '\n';
  }
  // The fields of the VTU and CSV forms, in the same order.
  const auto scalars = [&](const char* name, const std::vector<float>& v) {
    out << "SCALARS " << name << " float 1\nLOOKUP_TABLE default\n";
    for (std::size_t i = 0; i < n; ++i) out << v[i] << '\n';
  };
  scalars("density", p.density);
  scalars("pressure", p.pressure);
  scalars("mass", p.mass);
  scalars("radius", p.radius);
  out << "SCALARS level int 1\nLOOKUP_TABLE default\n";  // 0 for L0, the finest
  for (std::size_t i = 0; i < n; ++i) out << static_cast<int>(p.level[i]) << '\n';
  out << "SCALARS id unsigned_int 1\nLOOKUP_TABLE default\n";
  for (std::size_t i = 0; i < n; ++i) out << p.id[i] << '\n';
}

}  // namespace bench
