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
  // The fluid solver that steps the particles, by its name in solvers/fluid_solver_factory.h.
  std::string solver = "thesis";
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

  // The incompressible solvers. time_step stays the frame (a step of the simulation: what the
  // server publishes and the adaptive step follows); they take solver steps inside it.
  int substeps = 2;        // pbf: solver steps per frame; dfsph: at least this many (CFL may add)
  int pbf_iterations = 3;  // pbf: Jacobi iterations of the density constraint per solver step
  // pbf: past pbf_iterations, a step iterates on while its mean compression (rho / rho0 - 1
  // where positive) exceeds this, up to pbf_max_iterations; 0: pbf_iterations exactly.
  double pbf_density_tolerance = 0.0;
  int pbf_max_iterations = 20;
  double pbf_relaxation = 0.01;  // pbf: constraint force mixing, relative to a full neighbourhood's (MM13 eq. 11)
  // pbf (and dfsph's placement of split and merged particles): the Jacobi update's relaxation
  // factor, lambda += omega dlambda. Neighbours correct each other's density at the same time, so
  // the full step (1) overshoots and a resting tank oscillates.
  double pbf_omega = 0.5;
  double pbf_tensile_k = 0.1;  // pbf: artificial pressure s_corr = -k (W(r) / W(dq h))^n (MM13 eq. 13)
  double pbf_tensile_dq = 0.2;
  int pbf_tensile_n = 4;
  double xsph_viscosity = 0.01;        // c of XSPH velocity smoothing (MM13 eq. 17), both solvers
  double vorticity_confinement = 0.0;  // pbf: epsilon of vorticity confinement (MM13 eq. 16), m/s; 0: off
  double cfl = 0.4;                    // dfsph: solver step <= cfl * particle diameter / max speed
  int max_substeps = 40;               // dfsph: at most this many solver steps per frame
  double density_tolerance = 5e-4;     // dfsph: mean compression after the step the constant-density solver stops at
  double divergence_tolerance = 1e-3;  // dfsph: mean |d rho / dt| / rho0 * dt the divergence solver stops at
  int max_iterations = 100;            // dfsph: per solver, per step
  // dfsph: the constant-density solve turns from Jacobi to conjugate gradients after its first
  // three iterations (dfsph_conjugate_gradients.cpp): a third to half the iterations in deep
  // or resting water; a small tank at rest keeps moving at 2-3 mm/s where Jacobi brings it under
  // 1, a wide one moves less than under Jacobi (docs/fluids.md). On in dfsph's preset.
  bool conjugate_gradients = false;

  std::array<SizeClassProps, kSizeClassCount> classes() const;
  double surfaceThreshold() const;  // l, eq. (3.36)
  // Throws std::invalid_argument naming the offending key when a value is not finite or out of range.
  void validate() const;
};

SimParams thesisPreset();
SimParams pbfPreset();
SimParams dfsphPreset();
// Presets known by name; returns false when `name` is unknown.
bool presetByName(const std::string& name, SimParams& out);
const std::vector<std::string>& presetNames();

}  // namespace sph
