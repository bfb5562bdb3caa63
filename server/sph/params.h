// Simulation parameters. The `thesis` preset reproduces tables 3.1 and 3.2; every value can be
// overridden from a scene file. Derived quantities (radii, support radii) follow eqs. (3.7), (3.8).
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace sph {

enum class SizeClass : std::uint8_t { Small = 0, Large = 1 };
inline constexpr int kSizeClassCount = 2;

inline int classIndex(SizeClass c) { return static_cast<int>(c); }
const char* sizeClassName(SizeClass c);

// Per size class: what table 3.2 gives (mass, kernel particles x) and what follows from it.
struct SizeClassProps {
  double mass = 0.0;              // m (table 3.2)
  double kernel_particles = 0.0;  // x (table 3.2)
  double radius = 0.0;            // r = cbrt(3 m / (4 pi rho0)), eq. (3.7)
  double support = 0.0;           // h = cbrt(3 V x / (4 pi)), V = m / rho0, eq. (3.8)
};

struct SimParams {
  std::string preset = "thesis";
  // Table 3.1.
  double rest_density = 998.29;     // rho0
  double viscosity = 3.5;           // mu
  double surface_tension = 0.0728;  // sigma
  double gas_stiffness = 3.0;       // k
  double time_step = 0.01;          // dt
  double gravity = -9.81;           // g along y
  // Table 3.2 (masses and kernel particles per class; adaptive weights live with the methods).
  double mass_small = 0.01;
  double mass_large = 0.02;
  double kernel_particles_small = 50.0;
  double kernel_particles_large = 20.0;
  // Surface tension applies where |n| >= l, l = sqrt(rho0 / x_LARGE), eq. (3.36).
  // Also used by the surface-based adaptive method, eq. (3.44).
  bool surface_tension_enabled = true;
  // Steps between reorderings of the particle arrays into grid-cell order (cache locality).
  int resort_interval = 8;

  std::array<SizeClassProps, kSizeClassCount> classes() const;
  double surfaceThreshold() const;  // l, eq. (3.36)
  // Throws std::invalid_argument naming the offending key when a value is not finite or out of range.
  void validate() const;
};

SimParams thesisPreset();
// Presets known by name; returns false when `name` is unknown.
bool presetByName(const std::string& name, SimParams& out);

}  // namespace sph
