#include "sph/param_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "sph/solvers/dfsph/dfsph_parameters.h"
#include "sph/solvers/pbf/pbf_parameters.h"
#include "sph/solvers/thesis/thesis_parameters.h"

namespace sph {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMostSteps = 1e8;  // an integer without a natural ceiling still fits an int

// Shortest text that reads back as the same double (a range bound, a default).
std::string number(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char text[32];
  if (std::floor(v) == v && std::abs(v) < 1e15) {
    std::snprintf(text, sizeof text, "%.0f", v);
    return text;
  }
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    if (std::strtod(text, nullptr) == v) break;
  }
  return text;
}

// A Markdown table cell: a bar inside it would end the cell.
std::string cell(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

// The methods that read the character field (gaze only once its gaze is lost) and the gaze's age.
constexpr const char* kCharacter = "surface, hybrid, gaze";
constexpr const char* kGazed = "gaze, hybrid, foveated";

// The simulation parameters every solver reads. Ranges: min, max, whether min and max themselves
// are excluded.
std::vector<ParamSpec> sharedRows() {
  return {
      // The water and the frame (table 3.1).
      {"rest_density", nullptr, "all", &SimParams::rest_density, 0, kInf, true, true, "kg/m^3", "rest density rho0"},
      {"time_step", nullptr, "all", &SimParams::time_step, 0, kInf, true, true, "s",
       "the frame: simulated seconds a step advances (pbf and dfsph take solver steps inside it)"},
      {"gravity", nullptr, "all", &SimParams::gravity, -kInf, kInf, true, true, "m/s^2", "gravity along y"},
      // The particles (table 3.2; eqs. 3.7, 3.8).
      {"mass_small", nullptr, "all", &SimParams::mass_small, 0, kInf, true, true, "kg", "mass of an L0 particle"},
      {"mass_large", nullptr, "all", &SimParams::mass_large, 0, kInf, true, true, "kg",
       "mass of an L1 particle: twice mass_small (a split halves a particle, eq. 3.38)"},
      {"kernel_particles_small", nullptr, "all", &SimParams::kernel_particles_small, 0, kInf, true, true, "particles",
       "particles x in an L0 particle's support, which sets its radius (eq. 3.8)"},
      {"kernel_particles_large", nullptr, "all", &SimParams::kernel_particles_large, 0, kInf, true, true, "particles",
       "particles x in an L1 particle's support; also the surface threshold l (eq. 3.36)"},
      {"resort_interval", nullptr, "all", &SimParams::resort_interval, 1, kMostSteps, false, false, "steps",
       "steps between reorderings of the particle arrays into grid-cell order"},
      {"levels", nullptr, "all", &SimParams::levels, kMinLevels, kMaxLevels, false, false, "levels",
       "size levels the adaptive methods may use, L0 (the finest) to L(levels - 1), each twice the mass of the one "
       "below"},
  };
}

// The incompressible solvers' shared steps.
std::vector<ParamSpec> incompressibleRows() {
  return {
      {"substeps", nullptr, "pbf, dfsph", &SimParams::substeps, 1, 100, false, false, "",
       "solver steps a frame: pbf exactly this many, dfsph at least (its CFL bound may add)"},
      {"xsph_viscosity", nullptr, "pbf, dfsph", &SimParams::xsph_viscosity, 0, 1, false, false, "",
       "c of XSPH velocity smoothing, once a frame (MM13 eq. 17)"},
  };
}

std::vector<ParamSpec> adaptiveRows() {
  using A = AdaptiveConfig;
  return {
      // The character field (3.45, table 3.2): surface and hybrid, and gaze once the gaze is lost.
      {"alpha", nullptr, kCharacter, &A::alpha, 0, 1e6, false, false, "", "geometric weight of the character field"},
      {"beta", nullptr, kCharacter, &A::beta, 0, 1e6, false, false, "", "dynamic (pressure) weight"},
      {"gamma", nullptr, kCharacter, &A::gamma, 0, 1e6, false, false, "", "isolation weight"},
      {"threshold", nullptr, kCharacter, &A::threshold, 0, 1, false, false, "",
       "T of (3.46): split where the character is below T, merge where it is 2T or more"},
      {"surface_includes_walls", nullptr, kCharacter, &A::surface_includes_walls, 0, 1, false, false, "",
       "the box's walls count as boundary for d in (3.45) (the thesis's figure 3.2)"},
      {"surface_normal_scale", nullptr, kCharacter, &A::surface_normal_scale, 0, 100, false, false, "",
       "a surface particle has |n| >= this times l (3.44); 2 keeps the split band from creeping inwards"},
      // The gaze (docs/design.md section 3).
      {"gaze_radius", nullptr, "gaze, hybrid", &A::gaze_radius, 0, 2, false, false, "viewport widths",
       "radius of the gaze circle, inside which particles split"},
      {"gaze_ring_radius", "gaze_ring", "gaze, hybrid", &A::gaze_ring_radius, 0, 2, false, false, "viewport widths",
       "outer radius of the hysteresis ring (>= gaze_radius): between the two, particles keep their size"},
      {"gaze_stale_s", nullptr, kGazed, &A::gaze_stale_s, 0, 3600, false, false, "s",
       "a gaze sample older than this is held: its point stays in use"},
      {"gaze_hold_s", nullptr, kGazed, &A::gaze_hold_s, 0, 3600, false, false, "s",
       "a gaze sample older than this (>= gaze_stale_s) is lost: refinement falls back to the surface"},
      // The foveated method (adaptive/foveated.h).
      {"foveated_quality", nullptr, "foveated", &A::foveated_quality, 1, 1e3, false, false, "",
       "q: a particle may look q MAR(e) / MAR(0) finest widths wide; coarser everywhere as it grows"},
      {"foveated_periphery_gain", nullptr, "foveated", &A::foveated_periphery_gain, 1, 1e3, false, false, "",
       "g multiplies the eccentricity term except at the gaze point (the real-time governor's knob)"},
      {"foveated_mar_w0_deg", nullptr, "foveated", &A::foveated_mar_w0_deg, 1e-4, 10, false, false, "degrees",
       "w0 of the eye's minimum angle of resolution MAR(e) = w0 + m e"},
      {"foveated_mar_slope", nullptr, "foveated", &A::foveated_mar_slope, 0, 10, false, false, "degrees/degree",
       "m of MAR(e) = w0 + m e"},
      {"foveated_display_fov_deg", nullptr, "foveated", &A::foveated_display_fov_deg, 0, 179, false, false, "degrees",
       "how wide the display looks to the user; 0: the camera's own field of view"},
      {"foveated_hidden_depth", nullptr, "foveated", &A::foveated_hidden_depth, 0, 1e6, false, false, "finest spacings",
       "water deeper than this under the free surface is hidden: it may take the coarsest level whose support its "
       "depth covers"},
      {"foveated_coarsen_margin", nullptr, "foveated", &A::foveated_coarsen_margin, 1, 100, false, false, "",
       "coarsening waits until the eye allows this many times the next level's width (hysteresis)"},
      {"foveated_thin_fill", nullptr, "foveated", &A::foveated_thin_fill, 0, 1, false, false, "rho0",
       "water below this density (a sheet, a jet, a drop) stays at most at foveated_thin_level"},
      {"foveated_thin_level", nullptr, "foveated", &A::foveated_thin_level, 0, 7, false, false, "level",
       "the coarsest level thin and shallow water takes (at most the run's coarsest)"},
      {"foveated_shallow_spread", nullptr, "foveated", &A::foveated_shallow_spread, 0, 1, false, false, "",
       "water whose neighbours spread less than this share across their thinnest direction is shallow"},
      {"foveated_grading_step", nullptr, "foveated", &A::foveated_grading_step, 1, 7, false, false, "levels",
       "a particle may be at most this many levels coarser than its finest neighbour"},
      {"foveated_merge_hold_s", nullptr, "foveated", &A::foveated_merge_hold_s, 0, 600, false, false, "s",
       "a merge waits until the eye has allowed the coarser level this long; 0: at once"},
  };
}

// Every setting, the simulation parameters first, a solver's own from its folder, in the order
// docs/parameters.md lists them; registerParameter adds to it.
std::vector<ParamSpec>& rows() {
  static std::vector<ParamSpec> table = [] {
    std::vector<ParamSpec> all;
    for (const std::vector<ParamSpec>& part : {sharedRows(), thesisParameterRows(), incompressibleRows(),
                                               pbfParameterRows(), dfsphParameterRows(), adaptiveRows()}) {
      all.insert(all.end(), part.begin(), part.end());
    }
    return all;
  }();
  return table;
}

}  // namespace

const std::vector<ParamSpec>& parameterTable() { return rows(); }

const ParamSpec* findParameter(const std::string& name) {
  for (const ParamSpec& spec : parameterTable()) {
    if (name == spec.key || (spec.alias != nullptr && name == spec.alias)) return &spec;
  }
  return nullptr;
}

void registerParameter(const ParamSpec& spec) {
  for (const char* name : {spec.key, spec.alias}) {
    if (name != nullptr && findParameter(name) != nullptr) {
      throw std::invalid_argument(std::string("a setting called '") + name + "' exists already");
    }
  }
  rows().push_back(spec);
}

bool unregisterParameter(const std::string& key) {
  std::vector<ParamSpec>& table = rows();
  const auto it = std::find_if(table.begin(), table.end(), [&](const ParamSpec& s) { return key == s.key; });
  if (it == table.end()) return false;
  table.erase(it);
  return true;
}

// ParamField lists SimParams's three alternatives before AdaptiveConfig's.
bool ParamSpec::isAdaptive() const { return field.index() >= 3; }

bool ParamSpec::isReal() const {
  return std::holds_alternative<double SimParams::*>(field) || std::holds_alternative<double AdaptiveConfig::*>(field);
}

bool ParamSpec::isInteger() const {
  return std::holds_alternative<int SimParams::*>(field) || std::holds_alternative<int AdaptiveConfig::*>(field);
}

bool ParamSpec::isFlag() const {
  return std::holds_alternative<bool SimParams::*>(field) || std::holds_alternative<bool AdaptiveConfig::*>(field);
}

namespace {

// The field of `spec` in `holder` (a SimParams or an AdaptiveConfig), as a double.
template <class Holder>
double getIn(const ParamSpec& spec, const Holder& holder) {
  return std::visit(
      [&](auto member) -> double {
        if constexpr (std::is_invocable_v<decltype(member), const Holder&>) {
          return static_cast<double>(holder.*member);
        } else {
          throw std::logic_error(std::string("setting '") + spec.key + "' is not a field of this struct");
        }
      },
      spec.field);
}

template <class Holder>
void setIn(const ParamSpec& spec, Holder& holder, double value) {
  std::visit(
      [&](auto member) {
        if constexpr (std::is_invocable_v<decltype(member), Holder&>) {
          using T = std::remove_reference_t<decltype(holder.*member)>;
          if constexpr (std::is_same_v<T, bool>) {
            holder.*member = value != 0.0;
          } else {
            holder.*member = static_cast<T>(value);
          }
        } else {
          throw std::logic_error(std::string("setting '") + spec.key + "' is not a field of this struct");
        }
      },
      spec.field);
}

// Every row of one kind checked against `holder`'s fields: the first out of range throws.
template <class Holder>
void checkRows(const Holder& holder, bool adaptive) {
  for (const ParamSpec& spec : parameterTable()) {
    if (spec.isAdaptive() != adaptive) continue;
    const std::string why = spec.check(spec.get(holder));
    if (!why.empty()) throw std::invalid_argument(std::string("parameter '") + spec.key + "' " + why);
  }
}

}  // namespace

double ParamSpec::get(const SimParams& p) const { return getIn(*this, p); }
double ParamSpec::get(const AdaptiveConfig& c) const { return getIn(*this, c); }
void ParamSpec::set(SimParams& p, double value) const { setIn(*this, p, value); }
void ParamSpec::set(AdaptiveConfig& c, double value) const { setIn(*this, c, value); }

std::string ParamSpec::accepts() const {
  if (isFlag()) return "true or false";
  const std::string what = isInteger() ? "an integer" : "a number";
  if (std::isinf(min) && std::isinf(max)) return "a finite number";
  if (std::isinf(max)) return what + (min_open ? " > " : " >= ") + number(min);
  return what + " in " + (min_open ? "(" : "[") + number(min) + ", " + number(max) + (max_open ? ")" : "]");
}

std::string ParamSpec::check(double value) const {
  const bool whole = !isReal() ? std::floor(value) == value : true;
  const bool above = min_open ? value > min : value >= min;
  const bool below = max_open ? value < max : value <= max;
  if (std::isfinite(value) && whole && above && below) return {};
  return "must be " + accepts();
}

void checkRanges(const AdaptiveConfig& config) { checkRows(config, true); }

bool parseParameterSetting(const std::string& setting, std::map<std::string, double>& out, std::string& error) {
  const std::size_t eq = setting.find('=');
  if (eq == std::string::npos || eq == 0) {
    error = "expected KEY=VALUE";
    return false;
  }
  const std::string name = setting.substr(0, eq);
  const ParamSpec* spec = findParameter(name);
  if (spec == nullptr) {
    error = "unknown setting '" + name + "'";
    return false;
  }
  const std::string text = setting.substr(eq + 1);
  double value = std::numeric_limits<double>::quiet_NaN();
  if (spec->isFlag() && (text == "true" || text == "false")) {
    value = text == "true" ? 1.0 : 0.0;
  } else {
    char* end = nullptr;
    const double parsed = std::strtod(text.c_str(), &end);
    if (!text.empty() && end == text.c_str() + text.size()) value = parsed;
  }
  if (const std::string why = spec->check(value); !why.empty()) {
    error = std::string(spec->key) + " " + why;
    return false;
  }
  out[spec->key] = value;
  return true;
}

AdaptiveConfig withAdaptiveSettings(AdaptiveConfig config, const std::map<std::string, double>& values) {
  for (const auto& [name, value] : values) {
    const ParamSpec* spec = findParameter(name);
    if (spec == nullptr || !spec->isAdaptive()) throw std::invalid_argument("unknown adaptive setting '" + name + "'");
    if (const std::string why = spec->check(value); !why.empty()) {
      throw std::invalid_argument(std::string("parameter '") + spec->key + "' " + why);
    }
    spec->set(config, value);
  }
  config.validate();
  return config;
}

std::string parameterHelpText(bool adaptive) {
  std::size_t width = 0;
  for (const ParamSpec& spec : parameterTable()) {
    if (spec.isAdaptive() == adaptive) width = std::max(width, std::string(spec.key).size());
  }
  std::ostringstream out;
  for (const ParamSpec& spec : parameterTable()) {
    if (spec.isAdaptive() != adaptive) continue;
    out << "  " << spec.key << std::string(width + 2 - std::string(spec.key).size(), ' ') << "(" << spec.read_by << ") "
        << spec.accepts();
    if (*spec.unit != '\0') out << ", " << spec.unit;
    out << ": " << spec.description << "\n";
  }
  return out.str();
}

std::string parameterTableMarkdown() {
  const std::vector<std::string>& presets = presetNames();
  std::vector<SimParams> defaults(presets.size());
  for (std::size_t i = 0; i < presets.size(); ++i) presetByName(presets[i], defaults[i]);
  const AdaptiveConfig adaptive_defaults;
  const auto value = [](const ParamSpec& spec, double v) {
    return spec.isFlag() ? std::string(v != 0.0 ? "true" : "false") : number(v);
  };
  const auto row = [&](const ParamSpec& spec) {
    std::string text = "| `" + std::string(spec.key) + "`";
    if (spec.alias != nullptr) text += " (was `" + std::string(spec.alias) + "`)";
    return text + " | " + spec.read_by + " | " + spec.accepts() + " | " + cell(spec.unit) + " |";
  };
  std::ostringstream out;
  out << "| key | read by | takes | unit |";
  for (const std::string& name : presets) out << " " << name << " |";
  out << " what it is |\n|---|---|---|---|";
  for (std::size_t i = 0; i < presets.size(); ++i) out << "---|";
  out << "---|\n";
  for (const ParamSpec& spec : parameterTable()) {
    if (spec.isAdaptive()) continue;
    out << row(spec);
    for (const SimParams& p : defaults) out << " " << value(spec, spec.get(p)) << " |";
    out << " " << cell(spec.description) << " |\n";
  }
  out << "\nThe adaptive settings, a scene file's `adaptive` (`sph_server --adaptive`), are the same for "
         "every preset:\n\n| key | read by | takes | unit | default | what it is |\n|---|---|---|---|---|---|\n";
  for (const ParamSpec& spec : parameterTable()) {
    if (!spec.isAdaptive()) continue;
    out << row(spec) << " " << value(spec, spec.get(adaptive_defaults)) << " | " << cell(spec.description) << " |\n";
  }
  return out.str();
}

// The ranges above, then what holds between parameters.
void SimParams::validate() const {
  checkRows(*this, false);
  // A split halves a particle's mass (3.38) and a merge adds two (3.41): only then does every
  // particle of a class keep its class's mass, which mass by class and the pair passes rely on.
  if (mass_large != 2.0 * mass_small) throw std::invalid_argument("parameter 'mass_large' must be twice 'mass_small'");
  // The pair passes tell a neighbour's class, so its kernel and mass, by its support.
  const auto props = levelProps();
  bool supports_differ = true;
  for (std::size_t a = 0; a < props.size(); ++a) {
    for (std::size_t b = a + 1; b < props.size(); ++b) {
      supports_differ = supports_differ && static_cast<float>(props[a].support) != static_cast<float>(props[b].support);
    }
  }
  if (!supports_differ) {
    throw std::invalid_argument(
        "parameters 'kernel_particles_small' and 'kernel_particles_large' give two levels "
        "one support: the levels must differ in it");
  }
}

}  // namespace sph
