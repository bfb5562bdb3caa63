// sph_validate: the fluid presets against experiment and theory. The Martin & Moyce dam break
// (scenes/validation/martin_moyce.json): the surge front Z and the residual column height against
// T for every preset and method, as tables, CSVs and PNGs with the experiment's points; the
// hydrostatic tank (scenes/validation/hydrostatic.json): density and pressure against depth after
// settling.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "bench/bench_run.h"
#include "bench/validation.h"
#include "cli/cli_conventions.h"
#include "gaze/gaze_recording.h"
#include "process/omp_wait.h"
#include "scene/scene_loader.h"

namespace {

namespace fs = std::filesystem;

struct Options {
  std::vector<std::string> presets = {"pbf", "dfsph", "thesis"};
  std::vector<std::string> methods = {"regular", "surface", "gaze"};
  std::string scene_dir;
  std::string out = "validation_out";
  int threads = 2;
  int hydrostatic_frames = 0;  // 0: the scene's own
  // Gaze recordings for the methods that follow the gaze, each run once per recording; empty:
  // the scene's own.
  std::vector<std::string> gaze_files;
  bool plot = true;
};

struct FrontRun {
  std::string preset, method;
  bench::Column column;
  std::vector<bench::CurvePoint> curve;
  double error = 0.0, shifted_error = 0.0, shift = 0.0;
  // The residual column's height over the same gauges' reading at release; its errors unshifted
  // and with the front's shift (one start-up delay for both measurements).
  std::vector<bench::CurvePoint> height;
  double height_error = 0.0, height_shifted_error = 0.0;
};

constexpr double kGravity = 9.81;
constexpr double kTMax = 3.0;      // compared with the experiment for 0 < T <= 3
constexpr double kMaxShift = 0.2;  // the largest start-up shift in T allowed

// `label`: the method as the tables name the run (the method, with its gaze recording's name where
// it ran under several).
FrontRun runSurgeFront(const sph::Scene& scene, const std::string& method, const std::string& label,
                       const gaze::GazeRecording* gaze, int threads) {
  FrontRun out;
  out.preset = scene.params.preset;
  out.method = label;
  const double rho0 = scene.params.rest_density;
  const double wall_x = scene.boundary.box.min.x();
  double released_height = 0.0;  // the residual column's as the gauges read it at release
  bench::RunOptions options;
  options.threads = threads;
  options.gaze = gaze;
  options.on_frame = [&](const sph::Simulation& sim, const bench::FrameRecord& record) {
    const double a = out.column.width;
    const double T = record.sim_time * std::sqrt(2.0 * kGravity / a);
    out.curve.push_back({T, (bench::surgeFrontX(sim.particles(), rho0) - wall_x) / a});
    out.height.push_back({T, bench::residualHeight(sim.particles(), sim.scene(), sim.boxNow()) / released_height});
  };
  bench::SceneRun run(scene, method, options);
  out.column = bench::measureColumn(run.simulation().particles(), rho0, wall_x);
  const sph::ParticleSet& released = run.simulation().particles();
  out.curve.push_back({0.0, (bench::surgeFrontX(released, rho0) - wall_x) / out.column.width});
  released_height = bench::residualHeight(released, run.simulation().scene(), run.simulation().boxNow());
  out.height.push_back({0.0, 1.0});
  while (!run.done()) run.stepFrame();
  const auto& mm = bench::martinMoyceN2();
  out.error = bench::maxRelativeError(out.curve, mm, kTMax, 0.0);
  out.shift = bench::bestStartupShift(out.curve, mm, kTMax, kMaxShift, out.shifted_error);
  const auto& mm_height = bench::martinMoyceHeightN2();
  out.height_error = bench::maxRelativeError(out.height, mm_height, kTMax, 0.0);
  out.height_shifted_error = bench::maxRelativeError(out.height, mm_height, kTMax, out.shift);
  return out;
}

std::string percent(double x) {
  char text[32];
  std::snprintf(text, sizeof text, std::isfinite(x) ? "%.2f %%" : "n/a", 100.0 * x);
  return text;
}

// One curve of every run (`of`) as a CSV: preset, method, T and the value named `column`.
void writeCurves(const std::vector<FrontRun>& runs, std::vector<bench::CurvePoint> FrontRun::*of,
                 const std::string& column, const fs::path& file) {
  std::ofstream csv(file);
  csv << "preset,method,T," << column << '\n';
  for (const FrontRun& r : runs) {
    for (const auto& p : r.*of) csv << r.preset << ',' << r.method << ',' << p.T << ',' << p.value << '\n';
  }
}

void writeExperiment(const std::vector<bench::CurvePoint>& points, const std::string& column, const fs::path& file) {
  std::ofstream csv(file);
  csv << "T," << column << '\n';
  for (const auto& p : points) csv << p.T << ',' << p.value << '\n';
}

// The experiment's points beside every run's curve (`of`) at the same T.
void writeCurveTable(std::ostream& md, const std::vector<bench::CurvePoint>& experiment,
                     const std::vector<FrontRun>& runs, std::vector<bench::CurvePoint> FrontRun::*of,
                     const std::string& name) {
  md << "\n| T (experiment) | " << name << " (experiment) |";
  for (const FrontRun& r : runs) md << ' ' << r.preset << '/' << r.method << " |";
  md << "\n|---|---|";
  for (std::size_t k = 0; k < runs.size(); ++k) md << "---|";
  md << '\n';
  for (const auto& e : experiment) {
    const bool simulated = std::any_of(runs.begin(), runs.end(),
                                       [&](const FrontRun& r) { return std::isfinite(bench::curveAt(r.*of, e.T)); });
    if (!simulated) continue;  // past every run's last frame
    char cell[64];
    std::snprintf(cell, sizeof cell, "| %.2f | %.2f |", e.T, e.value);
    md << cell;
    for (const FrontRun& r : runs) {
      std::snprintf(cell, sizeof cell, " %.2f |", bench::curveAt(r.*of, e.T));
      md << cell;
    }
    md << '\n';
  }
}

void writeSurgeFront(const std::vector<FrontRun>& runs, const fs::path& dir) {
  writeCurves(runs, &FrontRun::curve, "Z", dir / "surge_front.csv");
  writeCurves(runs, &FrontRun::height, "height", dir / "residual_height.csv");
  writeExperiment(bench::martinMoyceN2(), "Z", dir / "martin_moyce_n2.csv");
  writeExperiment(bench::martinMoyceHeightN2(), "height", dir / "martin_moyce_height_n2.csv");
  std::ofstream md(dir / "surge_front.md");
  md << "# Surge front and residual column against Martin & Moyce (1952), n^2 = 2\n\n"
     << "Z = x_front / a against T = t sqrt(2 g / a); x_front is the 99.9th percentile of the particles' x plus "
        "half a spacing. Error: the largest |Z - Z_exp| / Z_exp at the experiment's points with 0 < T <= 3; "
        "'shifted': with the start-up shift in T (<= 0.2, the experiment's gate) that minimises it. "
        "The column as released: its height (n^2 = 2 asks for 2 a), its mean compression and largest "
        "density. The residual column: the level gauges read at the back wall (rho0 / 2 of the "
        "kernel-interpolated density) over their reading at release, against Martin & Moyce's h / (n^2 a); "
        "its largest relative error at the experiment's points with 0 < T <= 3, unshifted and with the "
        "front's shift.\n\n"
     << "| preset | method | a (m) | height / a | compression, mean | max rho / rho0 | max error | shift | max "
        "error shifted | residual height error | shifted |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const FrontRun& r : runs) {
    char row[384];
    char max_density[32] = "n/a";
    if (std::isfinite(r.column.max_density))
      std::snprintf(max_density, sizeof max_density, "%.3f", r.column.max_density);
    std::snprintf(row, sizeof row, "| %s | %s | %.4f | %.3f | %s | %s | %s | %.3f | %s | %s | %s |\n", r.preset.c_str(),
                  r.method.c_str(), r.column.width, r.column.height / r.column.width,
                  percent(r.column.mean_compression).c_str(), max_density, percent(r.error).c_str(), r.shift,
                  percent(r.shifted_error).c_str(), percent(r.height_error).c_str(),
                  percent(r.height_shifted_error).c_str());
    md << row;
  }
  writeCurveTable(md, bench::martinMoyceN2(), runs, &FrontRun::curve, "Z");
  writeCurveTable(md, bench::martinMoyceHeightN2(), runs, &FrontRun::height, "height");
}

// The gauges' depth over the depth sum m / rho0 fills (water_level.h), or n/a.
std::string depthRatio(const bench::WaterLevel& level) {
  if (level.gauges == 0 || level.incompressible_depth <= 0.0) return "n/a";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", level.depth / level.incompressible_depth);
  return buf;
}

void writeRestProfiles(const std::vector<std::pair<std::string, bench::RestProfile>>& profiles, double rho0,
                       const fs::path& dir) {
  std::ofstream csv(dir / "hydrostatic.csv");
  csv << "preset,depth_m,count,density_ratio,pressure_pa,hydrostatic_pa\n";
  for (const auto& [preset, r] : profiles) {
    for (const auto& b : r.bins) {
      if (b.count == 0) continue;
      csv << preset << ',' << b.depth << ',' << b.count << ',' << b.density_ratio << ',' << b.pressure << ','
          << rho0 * kGravity * b.depth << '\n';
    }
  }
  std::ofstream md(dir / "hydrostatic.md");
  md << "# Water at rest: the hydrostatic tank after settling\n\n"
     << "| preset | mean density error | wall and floor layers | their particles (rho / rho0) | rms speed (mm/s) | "
        "pressure slope / (rho0 g) | depth / incompressible depth |\n"
     << "|---|---|---|---|---|---|---|\n";
  for (const auto& [preset, r] : profiles) {
    char row[320];
    std::snprintf(row, sizeof row, "| %s | %s | %s | %.4f-%.4f | %.2f | %.3f | %s |\n", preset.c_str(),
                  percent(r.mean_density_error).c_str(), percent(r.wall_density_error).c_str(), r.wall_min, r.wall_max,
                  1000.0 * r.rms_speed, r.pressure_slope / (rho0 * kGravity), depthRatio(r.level).c_str());
    md << row;
  }
}

// A curve's gnuplot style: one colour per preset, and the k-th run of a preset its own dash
// pattern, so nine curves that nearly coincide can still be told apart.
std::string curveStyle(const std::string& preset, std::size_t k) {
  std::string style;
  if (preset == "pbf") style += " lc rgb '#0072b2'";
  if (preset == "dfsph") style += " lc rgb '#d55e00'";
  if (preset == "thesis") style += " lc rgb '#808080'";
  return style + " dt " + std::to_string(k % 5 + 1);
}

// PNGs through gnuplot (scripts/install_deps.sh installs it); skipped with a note when missing.
void plot(const std::vector<FrontRun>& runs, const std::vector<std::string>& presets, const fs::path& dir) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
    std::fprintf(stderr, "sph_validate: gnuplot not found: no PNGs (the CSVs and tables are written)\n");
    return;
  }
  std::ostringstream gp;
  gp << "set datafile separator ','\nset terminal pngcairo size 1100,700\n"
     << "set output '" << (dir / "surge_front.png").string() << "'\n"
     << "set title 'Surge front, Martin \\& Moyce n^2 = 2'\nset xlabel 'T = t sqrt(2g/a)'\n"
     << "set ylabel 'Z = x / a'\nset key left top\nset xrange [0:3.5]\n"
     << "plot '" << (dir / "martin_moyce_n2.csv").string()
     << "' using 1:2 every ::1 with points pt 7 ps 1.5 lc rgb 'black' title 'Martin \\& Moyce 1952'";
  const auto runCurves = [&](const std::string& csv) {
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const FrontRun& r = runs[k];
      const auto of_preset = std::count_if(runs.begin(), runs.begin() + static_cast<std::ptrdiff_t>(k),
                                           [&](const FrontRun& o) { return o.preset == r.preset; });
      gp << ", '" << (dir / csv).string() << "' using ((strcol(1) eq '" << r.preset << "' && strcol(2) eq '" << r.method
         << "') ? $3 : NaN):4 with lines lw 2" << curveStyle(r.preset, static_cast<std::size_t>(of_preset))
         << " title '" << r.preset << " " << r.method << "' noenhanced";
    }
  };
  runCurves("surge_front.csv");
  gp << "\nset output '" << (dir / "residual_height.png").string() << "'\n"
     << "set title 'Residual column, Martin \\& Moyce n^2 = 2'\nset ylabel 'height / initial height'\n"
     << "set key right top\nplot '" << (dir / "martin_moyce_height_n2.csv").string()
     << "' using 1:2 every ::1 with points pt 7 ps 1.5 lc rgb 'black' title 'Martin \\& Moyce 1952'";
  runCurves("residual_height.csv");
  gp << "\nset output '" << (dir / "hydrostatic.png").string() << "'\nset multiplot layout 1,2\n"
     << "set title 'Density against depth'\nset xlabel 'rho / rho0'\nset ylabel 'depth (m)'\nset yrange [*:*] reverse\n"
     << "set xrange [*:*]\nset key bottom left\nplot ";
  for (std::size_t k = 0; k < presets.size(); ++k) {
    gp << (k ? ", " : "") << "'" << (dir / "hydrostatic.csv").string() << "' using ((strcol(1) eq '" << presets[k]
       << "') ? $4 : NaN):2 with linespoints lw 2 title '" << presets[k] << "'";
  }
  gp << "\nset title 'Pressure against depth'\nset xlabel 'p (Pa)'\nplot '" << (dir / "hydrostatic.csv").string()
     << "' using 6:2 with lines lw 2 dt 2 lc rgb 'black' title 'rho0 g depth'";
  for (const std::string& preset : presets) {
    gp << ", '" << (dir / "hydrostatic.csv").string() << "' using ((strcol(1) eq '" << preset
       << "') ? $5 : NaN):2 with linespoints lw 2 title '" << preset << "'";
  }
  gp << "\nunset multiplot\n";
  const fs::path script = dir / "plots.gp";
  std::ofstream(script) << gp.str();
  const std::string command = "gnuplot '" + script.string() + "'";
  if (std::system(command.c_str()) != 0) std::fprintf(stderr, "sph_validate: gnuplot failed on %s\n", script.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  process::applyDefaultOmpWaitPolicy(argv);  // first: it may re-execute the program
  Options o;
  o.scene_dir = (fs::path(scene::defaultSceneDir()) / "validation").string();
  CLI::App app{"sph_validate: the fluid presets against the Martin & Moyce dam break and a tank at rest"};
  cli::prepare(app, "sph_validate");
  app.add_option("--preset", o.presets, "presets to validate (thesis, pbf, dfsph)")
      ->delimiter(',')
      ->check(CLI::IsMember(sph::presetNames()));
  app.add_option("--method", o.methods, "methods for the dam break (regular, surface, gaze, hybrid, foveated)")
      ->delimiter(',')
      ->check(CLI::IsMember(sph::methodNames()));
  app.add_option("--scene-dir", o.scene_dir, "folder with martin_moyce.json and hydrostatic.json")
      ->capture_default_str();
  app.add_option("--out", o.out, "output folder")->capture_default_str();
  app.add_option("--threads", o.threads, "OpenMP threads")->check(cli::range(1, 256))->capture_default_str();
  app.add_option("--hydrostatic-frames", o.hydrostatic_frames, "frames the tank settles for (0: the scene's own)")
      ->check(cli::nonNegative());
  app.add_flag("!--no-plot", o.plot, "write no PNGs");
  app.add_option("--gaze", o.gaze_files,
                 "gaze recordings (CSV: time_s,x,y,valid) for gaze, hybrid and foveated, each a run of its own "
                 "(default: the scene's own)")
      ->delimiter(',')
      ->check(CLI::ExistingFile);
  if (auto code = cli::parse(app, argc, argv)) return *code;
  try {
    const fs::path dir(o.out);
    fs::create_directories(dir);
    std::vector<FrontRun> fronts;
    std::vector<std::pair<std::string, bench::RestProfile>> profiles;
    double rho0 = 0.0;
    for (const std::string& preset : o.presets) {
      const sph::Scene dam = scene::loadScene("martin_moyce", o.scene_dir, preset);
      std::vector<std::string> gaze_files = o.gaze_files;
      if (gaze_files.empty() && !dam.gaze_recording.empty()) gaze_files.push_back(dam.gaze_recording);
      std::vector<gaze::GazeRecording> recordings;
      for (const std::string& file : gaze_files) recordings.push_back(gaze::readGazeRecording(file));
      for (const std::string& method : o.methods) {
        const bool per_recording = bench::methodNeedsGaze(method) && recordings.size() > 1;
        for (std::size_t k = 0; k < (per_recording ? recordings.size() : 1); ++k) {
          // "foveated@martin_moyce_far_wall" for the recording martin_moyce_far_wall.gaze.csv.
          const std::string label =
              per_recording ? method + "@" + fs::path(gaze_files[k]).stem().stem().string() : method;
          fronts.push_back(runSurgeFront(dam, method, label, recordings.empty() ? nullptr : &recordings[k], o.threads));
          const FrontRun& r = fronts.back();
          std::fprintf(stderr,
                       "[martin_moyce %s/%s] released at %.3f a high, %s mean compression; max front error (T <= 3) "
                       "%s, with a shift of %.3f: %s; residual height error %s, shifted %s\n",
                       preset.c_str(), label.c_str(), r.column.height / r.column.width,
                       percent(r.column.mean_compression).c_str(), percent(r.error).c_str(), r.shift,
                       percent(r.shifted_error).c_str(), percent(r.height_error).c_str(),
                       percent(r.height_shifted_error).c_str());
        }
      }
      const sph::Scene tank = scene::loadScene("hydrostatic", o.scene_dir, preset);
      rho0 = tank.params.rest_density;
      bench::RunOptions options;
      options.threads = o.threads;
      options.frames = o.hydrostatic_frames;
      bench::SceneRun run(tank, tank.method, options);
      while (!run.done()) run.stepFrame();
      const sph::BoxState box = run.simulation().boxNow();
      const auto& p = run.simulation().particles();
      const double spacing = std::cbrt(p.mass.empty() ? 0.0 : p.mass[0] / rho0);
      profiles.emplace_back(preset, bench::measureRestProfile(p, rho0, box.min, box.max, 2.0 * spacing));
      bench::RestProfile& r = profiles.back().second;
      r.level = bench::measureWaterLevel(p, run.simulation().scene(), box);
      std::fprintf(stderr,
                   "[hydrostatic %s] mean density error %s, wall/floor %s (particles %.4f-%.4f rho0), rms speed "
                   "%.2f mm/s, pressure slope %.3f rho0 g, depth / incompressible depth %s\n",
                   preset.c_str(), percent(r.mean_density_error).c_str(), percent(r.wall_density_error).c_str(),
                   r.wall_min, r.wall_max, 1000.0 * r.rms_speed, r.pressure_slope / (rho0 * kGravity),
                   depthRatio(r.level).c_str());
    }
    writeSurgeFront(fronts, dir);
    writeRestProfiles(profiles, rho0, dir);
    if (o.plot) plot(fronts, o.presets, dir);
    std::printf("%s\n%s\n", (dir / "surge_front.md").c_str(), (dir / "hydrostatic.md").c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sph_validate: error: %s\n", e.what());
    return cli::kExitFailure;
  }
  return cli::kExitOk;
}
