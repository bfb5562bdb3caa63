#include "sph/param_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <type_traits>

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

}  // namespace

// Ranges: min, max, whether min and max themselves are excluded.
const std::vector<ParamSpec>& parameterTable() {
  static const std::vector<ParamSpec> table = {
      // The water and the frame (table 3.1).
      {"rest_density", nullptr, "all", &SimParams::rest_density, 0, kInf, true, true, "rest density rho0, kg/m^3"},
      {"time_step", nullptr, "all", &SimParams::time_step, 0, kInf, true, true,
       "the frame: simulated seconds a step advances (pbf and dfsph take solver steps inside it)"},
      {"gravity", nullptr, "all", &SimParams::gravity, -kInf, kInf, true, true, "gravity along y, m/s^2"},
      // The particles (table 3.2; eqs. 3.7, 3.8).
      {"mass_small", nullptr, "all", &SimParams::mass_small, 0, kInf, true, true, "mass of an L0 particle, kg"},
      {"mass_large", nullptr, "all", &SimParams::mass_large, 0, kInf, true, true,
       "mass of an L1 particle, kg: twice mass_small (a split halves a particle, eq. 3.38)"},
      {"kernel_particles_small", nullptr, "all", &SimParams::kernel_particles_small, 0, kInf, true, true,
       "particles x in an L0 particle's support, which sets its radius (eq. 3.8)"},
      {"kernel_particles_large", nullptr, "all", &SimParams::kernel_particles_large, 0, kInf, true, true,
       "particles x in an L1 particle's support; also the surface threshold l (eq. 3.36)"},
      {"resort_interval", nullptr, "all", &SimParams::resort_interval, 1, kMostSteps, false, false,
       "steps between reorderings of the particle arrays into grid-cell order"},
      {"levels", nullptr, "all", &SimParams::levels, kMinLevels, kMaxLevels, false, false,
       "size levels the adaptive methods may use, L0 (the finest) to L(levels - 1), each twice the mass of the one "
       "below"},
      // The thesis's forces (3.3-3.5).
      {"gas_stiffness", nullptr, "thesis", &SimParams::gas_stiffness, 0, kInf, true, true,
       "k of the state equation p = k (rho - rho0), eq. (3.12)"},
      {"viscosity", nullptr, "thesis", &SimParams::viscosity, 0, kInf, false, true,
       "dynamic viscosity mu of the viscosity force, eq. (3.14)"},
      {"surface_tension", nullptr, "thesis", &SimParams::surface_tension, 0, kInf, false, true,
       "sigma of the surface-tension force, eqs. (3.16)-(3.19)"},
      {"surface_tension_enabled", nullptr, "thesis", &SimParams::surface_tension_enabled, 0, 1, false, false,
       "surface tension where |n| >= l, eq. (3.36)"},
      // The incompressible solvers' shared steps.
      {"substeps", nullptr, "pbf, dfsph", &SimParams::substeps, 1, 100, false, false,
       "solver steps a frame: pbf exactly this many, dfsph at least (its CFL bound may add)"},
      {"xsph_viscosity", nullptr, "pbf, dfsph", &SimParams::xsph_viscosity, 0, 1, false, false,
       "c of XSPH velocity smoothing, once a frame (MM13 eq. 17)"},
      {"pbf_relaxation", nullptr, "pbf, dfsph", &SimParams::pbf_relaxation, 0, kInf, true, true,
       "constraint force mixing, relative to a full neighbourhood's (MM13 eq. 11); dfsph's placement too"},
      {"pbf_omega", nullptr, "pbf, dfsph", &SimParams::pbf_omega, 0, 1, true, false,
       "relaxation of the Jacobi update, lambda += omega dlambda; dfsph's placement too"},
      // Position based fluids (Macklin & Mueller 2013).
      {"pbf_iterations", nullptr, "pbf", &SimParams::pbf_iterations, 1, 100, false, false,
       "least Jacobi iterations of the density constraint a solver step (MM13 algorithm 1)"},
      {"pbf_density_tolerance", nullptr, "pbf", &SimParams::pbf_density_tolerance, 0, kInf, false, true,
       "past pbf_iterations, iterate on while the mean compression exceeds this; 0: exactly pbf_iterations"},
      {"pbf_max_iterations", nullptr, "pbf", &SimParams::pbf_max_iterations, 1, 100, false, false,
       "most Jacobi iterations a solver step"},
      {"pbf_tensile_k", nullptr, "pbf", &SimParams::pbf_tensile_k, 0, kInf, false, true,
       "k of the artificial pressure s_corr = -k (W(r) / W(dq h))^n (MM13 eq. 13); 0: off"},
      {"pbf_tensile_dq", nullptr, "pbf", &SimParams::pbf_tensile_dq, 0, 1, true, true,
       "dq of the artificial pressure, in supports"},
      {"pbf_tensile_n", nullptr, "pbf", &SimParams::pbf_tensile_n, 1, 8, false, false, "n of the artificial pressure"},
      {"vorticity_confinement", nullptr, "pbf", &SimParams::vorticity_confinement, 0, kInf, false, true,
       "epsilon of vorticity confinement, m/s (MM13 eq. 16); 0: off"},
      // Divergence-free SPH (Bender & Koschier 2015, 2017).
      {"dfsph_cfl", "cfl", "dfsph", &SimParams::dfsph_cfl, 0, 1, true, false,
       "no particle moves more than this share of its diameter in a solver step (BK17 eq. 15)"},
      {"dfsph_max_substeps", "max_substeps", "dfsph", &SimParams::dfsph_max_substeps, 1, 1000, false, false,
       "most solver steps a frame"},
      {"dfsph_density_tolerance", "density_tolerance", "dfsph", &SimParams::dfsph_density_tolerance, 0, kInf, true,
       true, "the constant-density solve stops at this mean compression after the step"},
      {"dfsph_divergence_tolerance", "divergence_tolerance", "dfsph", &SimParams::dfsph_divergence_tolerance, 0, kInf,
       true, true, "the divergence solve stops at this mean |d rho / dt| / rho0 * dt"},
      {"dfsph_max_iterations", "max_iterations", "dfsph", &SimParams::dfsph_max_iterations, 1, 10000, false, false,
       "most iterations of each solve a solver step"},
      {"dfsph_conjugate_gradients", "conjugate_gradients", "dfsph", &SimParams::dfsph_conjugate_gradients, 0, 1, false,
       false, "the constant-density solve turns from Jacobi to conjugate gradients after three iterations"},
  };
  return table;
}

const ParamSpec* findParameter(const std::string& name) {
  for (const ParamSpec& spec : parameterTable()) {
    if (name == spec.key || (spec.alias != nullptr && name == spec.alias)) return &spec;
  }
  return nullptr;
}

double ParamSpec::get(const SimParams& p) const {
  return std::visit([&](auto member) { return static_cast<double>(p.*member); }, field);
}

void ParamSpec::set(SimParams& p, double value) const {
  std::visit(
      [&](auto member) {
        using T = std::remove_reference_t<decltype(p.*member)>;
        if constexpr (std::is_same_v<T, bool>) {
          p.*member = value != 0.0;
        } else {
          p.*member = static_cast<T>(value);
        }
      },
      field);
}

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

bool parseParameterSetting(const std::string& setting, std::map<std::string, double>& out, std::string& error) {
  const std::size_t eq = setting.find('=');
  const ParamSpec* spec = eq == std::string::npos ? nullptr : findParameter(setting.substr(0, eq));
  if (spec == nullptr) {
    error = "expected KEY=VALUE with KEY a simulation parameter (see --help)";
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

std::string parameterHelpText() {
  std::size_t width = 0;
  for (const ParamSpec& spec : parameterTable()) width = std::max(width, std::string(spec.key).size());
  std::ostringstream out;
  for (const ParamSpec& spec : parameterTable()) {
    out << "  " << spec.key << std::string(width + 2 - std::string(spec.key).size(), ' ') << "(" << spec.solvers << ") "
        << spec.accepts() << ": " << spec.description << "\n";
  }
  return out.str();
}

std::string parameterTableMarkdown() {
  const std::vector<std::string>& presets = presetNames();
  std::vector<SimParams> defaults(presets.size());
  for (std::size_t i = 0; i < presets.size(); ++i) presetByName(presets[i], defaults[i]);
  std::ostringstream out;
  out << "| key | read by | takes |";
  for (const std::string& name : presets) out << " " << name << " |";
  out << " what it is |\n|---|---|---|";
  for (std::size_t i = 0; i < presets.size(); ++i) out << "---|";
  out << "---|\n";
  for (const ParamSpec& spec : parameterTable()) {
    out << "| `" << spec.key << "`";
    if (spec.alias != nullptr) out << " (was `" << spec.alias << "`)";
    out << " | " << spec.solvers << " | " << spec.accepts() << " |";
    for (const SimParams& p : defaults) {
      const double v = spec.get(p);
      out << " " << (spec.isFlag() ? (v != 0.0 ? "true" : "false") : number(v)) << " |";
    }
    out << " " << cell(spec.description) << " |\n";
  }
  return out.str();
}

// The ranges above, then what holds between parameters.
void SimParams::validate() const {
  for (const ParamSpec& spec : parameterTable()) {
    const std::string why = spec.check(spec.get(*this));
    if (!why.empty()) throw std::invalid_argument(std::string("parameter '") + spec.key + "' " + why);
  }
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
