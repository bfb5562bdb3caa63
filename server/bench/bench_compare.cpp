#include "bench/bench_compare.h"

#include <algorithm>
#include <cstdio>
#include <functional>

namespace bench {

namespace {

template <typename T>
void addUnique(std::vector<T>& list, const T& value) {
  if (std::find(list.begin(), list.end(), value) == list.end()) list.push_back(value);
}

// A markdown table's head: `first` over the row labels, then one right-aligned column each.
std::string tableHead(const std::string& first, const std::vector<std::string>& columns) {
  std::string head = "| " + first + " |";
  for (const auto& c : columns) head += ' ' + c + " |";
  head += "\n|---|";
  for (std::size_t k = 0; k < columns.size(); ++k) head += "---:|";
  return head + "\n";
}

// A markdown table's row: `label`, then cell(column) for each column.
template <class Cell>
std::string tableRow(const std::string& label, const std::vector<std::string>& columns, Cell cell) {
  std::string row = "| " + label + " |";
  for (const auto& c : columns) row += ' ' + cell(c) + " |";
  return row + "\n";
}

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

}  // namespace

std::string comparisonMarkdown(const std::vector<RunSummary>& runs) {
  std::vector<std::string> scenes;
  std::vector<std::string> methods;
  for (const auto& r : runs) {
    addUnique(scenes, r.run.scene);
    addUnique(methods, r.run.method);
  }
  const auto presetsOf = [&](const std::string& scene) {
    std::vector<std::string> presets;
    for (const auto& r : runs) {
      if (r.run.scene == scene) addUnique(presets, r.run.preset);
    }
    return presets;
  };
  const auto find = [&](const std::string& scene, const std::string& preset,
                        const std::string& method) -> const RunSummary* {
    for (const auto& r : runs) {
      if (r.run.scene == scene && r.run.preset == preset && r.run.method == method) return &r;
    }
    return nullptr;
  };
  struct Row {
    const char* label;
    std::function<std::string(const RunSummary&)> value;
  };
  const std::vector<Row> rows = {
      {"Neighbour search (ms)", [](const RunSummary& r) { return fixed(r.summary.neighbor.mean, 3); }},
      {"Density & Pressure (ms)", [](const RunSummary& r) { return fixed(r.summary.density_pressure.mean, 3); }},
      {"Acceleration, Integration & Collision (ms)",
       [](const RunSummary& r) { return fixed(r.summary.accel_integrate_collide.mean, 3); }},
      {"Adaptive step (ms)", [](const RunSummary& r) { return fixed(r.summary.adaptive.mean, 3); }},
      {"**Total (ms)**",
       [](const RunSummary& r) {
         std::string bold = "**";
         bold += fixed(r.summary.total.mean, 3);
         bold += "**";
         return bold;
       }},
      {"Total p95 (ms)", [](const RunSummary& r) { return fixed(r.summary.total.p95, 3); }},
      {"Adaptive share of step",
       [](const RunSummary& r) {
         const double t = r.summary.total.mean;
         return t > 0.0 ? fixed(100.0 * r.summary.adaptive.mean / t, 1) + " %" : std::string("-");
       }},
      {"Steps per second", [](const RunSummary& r) { return fixed(r.summary.steps_per_s, 1); }},
      {"Wall s per simulated s", [](const RunSummary& r) { return fixed(r.summary.wall_per_simulated, 2); }},
      {"Mean LARGE / SMALL",  // the thesis's names for L1 and L0
       [](const RunSummary& r) {
         return fixed(r.summary.mean_levels[1], 0) + " / " + fixed(r.summary.mean_levels[0], 0);
       }},
      {"Mean L0 / L1 / ...",
       [](const RunSummary& r) {
         std::string text;
         for (int k = 0; k < r.summary.levels; ++k) {
           if (k > 0) text += " / ";
           text += fixed(r.summary.mean_levels[static_cast<std::size_t>(k)], 0);
         }
         return text;
       }},
      {"Mean particles",
       [](const RunSummary& r) {
         double n = 0.0;
         for (const double c : r.summary.mean_levels) n += c;
         return fixed(n, 0);
       }},
      {"Perceptual budget exceeded (mean / max share of visible)",
       [](const RunSummary& r) {
         return fixed(100.0 * r.summary.mean_over_budget_share, 2) + " / " +
                fixed(100.0 * r.summary.max_over_budget_share, 2) + " %";
       }},
      {"Under the gaze: L0 share, width / MAR (arcmin)",
       [](const RunSummary& r) {
         if (r.summary.gaze_on_water_frames == 0) return std::string("-");
         return fixed(100.0 * r.summary.gaze_finest_share, 0) + " %, " + fixed(r.summary.mean_fovea_width_arcmin, 1) +
                " / " + fixed(r.summary.mean_fovea_mar_arcmin, 2);
       }},
      {"Saccades with L0 under the gaze by their third frame",
       [](const RunSummary& r) {
         if (r.summary.saccades_on_water == 0) return std::string("-");
         return std::to_string(r.summary.saccades_finest_in_time) + " of " +
                std::to_string(r.summary.saccades_on_water);
       }},
      {"Mean neighbours", [](const RunSummary& r) { return fixed(r.summary.mean_neighbors, 1); }},
      {"rho/rho0 mean / max",
       [](const RunSummary& r) {
         return fixed(r.summary.mean_density_ratio, 2) + " / " + fixed(r.summary.max_density_ratio, 1);
       }},
      {"NaN / outside box",
       [](const RunSummary& r) {
         return std::to_string(r.summary.nan_values) + " / " + std::to_string(r.summary.outside_box);
       }},
      {"Mass start = end",
       [](const RunSummary& r) { return std::string(r.run.mass_start == r.run.mass_end ? "yes" : "NO"); }},
  };

  std::string md = "# Methods compared (thesis table 5.x layout)\n\n";
  md +=
      "Mean milliseconds per step and phase; the neighbour search is shown on its own (the thesis "
      "folds it into the density row).\n";
  for (const std::string& scene : scenes) {
    const std::vector<std::string> presets = presetsOf(scene);
    for (const std::string& preset : presets) {
      md += "\n## ";
      md += scene;
      if (presets.size() > 1) md += ", preset " + preset;
      md += "\n\n" + tableHead("phase", methods);
      // A row of the methods' cells: what `value` reads from each run, "-" where it did not run.
      const auto methodRow = [&](const std::string& label, const auto& value) {
        return tableRow(label, methods, [&](const std::string& m) {
          const RunSummary* r = find(scene, preset, m);
          return r ? value(*r) : std::string("-");
        });
      };
      for (const Row& row : rows) md += methodRow(row.label, row.value);
      const RunSummary* regular = find(scene, preset, "regular");
      if (regular && regular->summary.total.mean > 0.0) {
        md += methodRow("Total / regular", [&](const RunSummary& r) {
          return fixed(r.summary.total.mean / regular->summary.total.mean, 2);
        });
        // What a particle costs against a regular one: the step's time over the mean particle count.
        const auto perParticle = [](const RunSummary& r) {
          double n = 0.0;
          for (const double c : r.summary.mean_levels) n += c;
          return n > 0.0 ? r.summary.total.mean / n : 0.0;
        };
        if (perParticle(*regular) > 0.0) {
          md += methodRow("Cost per particle / regular's",
                          [&](const RunSummary& r) { return fixed(perParticle(r) / perParticle(*regular), 2); });
        }
      }
      const RunSummary* any = nullptr;
      for (const auto& m : methods) any = any ? any : find(scene, preset, m);
      if (any) {
        md += '\n';
        md += framesText(any->run);
        md += ", ";
        md += std::to_string(any->run.threads);
        md += " threads (OpenMP wait: ";
        md += any->run.omp_wait;
        md += "), preset ";
        md += any->run.preset;
        md += ". Other load while the scene ran: ";
        md += describe(any->run.machine_load);
        md += ".\n";
      }
    }
    if (presets.size() < 2) continue;
    // The presets took turns in one run (bench_plan.h), so a slow spell of the machine fell on all
    // of them: their ratio is the figure to compare across runs, not the seconds.
    md += "\n### ";
    md += scene;
    md += ": presets compared\n\nWall-clock seconds per simulated second; in brackets, against ";
    md += presets.front();
    md += " in the same run.\n\n" + tableHead("method", presets);
    for (const auto& m : methods) {
      const RunSummary* first = find(scene, presets.front(), m);
      if (first == nullptr) continue;
      md += tableRow(m, presets, [&](const std::string& p) {
        const RunSummary* r = find(scene, p, m);
        if (r == nullptr) return std::string("-");
        std::string cell = fixed(r->summary.wall_per_simulated, 2);
        if (first->summary.wall_per_simulated > 0.0) {
          cell += " (" + fixed(r->summary.wall_per_simulated / first->summary.wall_per_simulated, 2) + ")";
        }
        return cell;
      });
    }
  }
  return md;
}

}  // namespace bench
