// Simulation parameters and the presets that set them. `thesis` reproduces tables 3.1 and 3.2 (a
// weakly compressible fluid, p = k (rho - rho0)); `pbf` (Macklin & Mueller 2013) and `dfsph`
// (Bender & Koschier 2015, 2017) keep the water's volume, with walls that count in the density
// (boundary_volume.h). Every value can be overridden from a scene file. Derived quantities (radii,
// support radii) follow eqs. (3.7), (3.8) for every preset.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "sph/solvers/dfsph/dfsph_parameters.h"
#include "sph/solvers/pbf/pbf_parameters.h"
#include "sph/solvers/thesis/thesis_parameters.h"

namespace sph {

// A particle's size level: L0 is the finest, and level k has mass 2^k m, so a split halves a
// particle into two of the level below and a merge joins two of one level into one of the level
// above, as (3.37)-(3.43) do for the thesis's two classes, and mass stays exact through any number
// of changes. The thesis's L0 and L1 are L0 and L1 of a two-level run. A run uses
// SimParams::levels of them (2 to kMaxLevels).
enum class Level : std::uint8_t {};
inline constexpr int kMaxLevels = 8;
inline constexpr int kMinLevels = 2;
// The thesis's methods use the first two levels only.
inline constexpr int kThesisLevels = 2;

inline int levelIndex(Level c) { return static_cast<int>(c); }
inline Level asLevel(int level) { return static_cast<Level>(level); }
// "L0", "L1", ... "L7"; "L?" for a value past kMaxLevels.
const char* levelName(Level c);

// Per level: what table 3.2 gives (mass, kernel particles x) and what follows from it.
struct LevelProps {
  double mass = 0.0;              // m (table 3.2)
  double kernel_particles = 0.0;  // x (table 3.2)
  double radius = 0.0;            // r = cbrt(3 m / (4 pi rho0)), eq. (3.7)
  double support = 0.0;           // h = cbrt(3 V x / (4 pi)), V = m / rho0, eq. (3.8)
};

// Every field is a parameter of param_table.h, which gives its key, range and meaning; the
// defaults here are the thesis's (thesisPreset), the other presets set their own (params.cpp).
// What one solver alone reads is declared in its folder (solvers/<name>/<name>_parameters.h) and
// inherited, so `params.pbf_iterations` reads as the shared fields do. Being bases, they rule out
// designated initializers: presets assign fields one by one.
struct SimParams : ThesisParams, PbfParams, DfsphParams {
  std::string preset = "thesis";
  // The fluid solver that steps the particles, by its name in solvers/fluid_solver_factory.h.
  std::string solver = "thesis";
  // Table 3.1 (the forces are the thesis solver's: ThesisParams).
  double rest_density = 998.29;
  double time_step = 0.01;
  double gravity = -9.81;
  // Table 3.2 (adaptive weights live with the methods).
  double mass_small = 0.01;
  double mass_large = 0.02;
  double kernel_particles_small = 50.0;
  double kernel_particles_large = 20.0;
  int resort_interval = 8;
  // How many size levels the adaptive methods may use, L0 to L(levels - 1); the thesis's methods
  // use the first two.
  int levels = 4;

  // The incompressible solvers: time_step stays the frame (a step of the simulation: what the
  // server publishes and the adaptive step follows); they take solver steps inside it.
  int substeps = 2;
  double xsph_viscosity = 0.01;

  // Every level's properties up to kMaxLevels: L0 and L1 from table 3.2; Lk, k >= 2, has mass
  // 2^(k-1) mass_large and L1's kernel particles (the support grows with the particle).
  std::array<LevelProps, kMaxLevels> levelProps() const;
  double surfaceThreshold() const;  // l, eq. (3.36)
  // Throws std::invalid_argument naming the offending key when a value is out of its range
  // (param_table.h, which defines this) or the masses and supports do not fit together.
  void validate() const;
};

SimParams thesisPreset();
SimParams pbfPreset();
SimParams dfsphPreset();
// Presets known by name; returns false when `name` is unknown.
bool presetByName(const std::string& name, SimParams& out);
const std::vector<std::string>& presetNames();
// presetNames() and "scene" (each scene file's own preset): what the programs' --preset takes.
std::vector<std::string> presetOrSceneNames();

}  // namespace sph
