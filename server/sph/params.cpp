#include "sph/params.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sph {

const char* sizeClassName(SizeClass c) { return c == SizeClass::Small ? "SMALL" : "LARGE"; }

namespace {

SizeClassProps deriveClass(double mass, double kernel_particles, double rho0) {
  SizeClassProps p;
  p.mass = mass;
  p.kernel_particles = kernel_particles;
  p.radius = std::cbrt(3.0 * mass / (4.0 * std::numbers::pi * rho0));  // (3.7)
  const double volume = mass / rho0;
  p.support = std::cbrt(3.0 * volume * kernel_particles / (4.0 * std::numbers::pi));  // (3.8)
  return p;
}

void requirePositive(double value, const char* key) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw std::invalid_argument(std::string("parameter '") + key + "' must be a finite number > 0");
  }
}

void requireFinite(double value, const char* key) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument(std::string("parameter '") + key + "' must be a finite number");
  }
}

}  // namespace

std::array<SizeClassProps, kSizeClassCount> SimParams::classes() const {
  return {deriveClass(mass_small, kernel_particles_small, rest_density),
          deriveClass(mass_large, kernel_particles_large, rest_density)};
}

double SimParams::surfaceThreshold() const { return std::sqrt(rest_density / kernel_particles_large); }

void SimParams::validate() const {
  requirePositive(rest_density, "rest_density");
  requireFinite(viscosity, "viscosity");
  if (viscosity < 0.0) throw std::invalid_argument("parameter 'viscosity' must be >= 0");
  requireFinite(surface_tension, "surface_tension");
  if (surface_tension < 0.0) throw std::invalid_argument("parameter 'surface_tension' must be >= 0");
  requirePositive(gas_stiffness, "gas_stiffness");
  requirePositive(time_step, "time_step");
  requireFinite(gravity, "gravity");
  requirePositive(mass_small, "mass_small");
  requirePositive(mass_large, "mass_large");
  // A split halves a particle's mass (3.38) and a merge adds two (3.41): only then does every
  // particle of a class keep its class's mass, which mass by class and the pair passes rely on.
  if (mass_large != 2.0 * mass_small) throw std::invalid_argument("parameter 'mass_large' must be twice 'mass_small'");
  requirePositive(kernel_particles_small, "kernel_particles_small");
  requirePositive(kernel_particles_large, "kernel_particles_large");
  // The pair passes tell a neighbour's class, so its kernel and mass, by its support.
  const auto props = classes();
  if (static_cast<float>(props[0].support) == static_cast<float>(props[1].support)) {
    throw std::invalid_argument(
        "parameters 'kernel_particles_small' and 'kernel_particles_large' give both classes "
        "one support: the classes must differ in it");
  }
  if (resort_interval < 1) throw std::invalid_argument("parameter 'resort_interval' must be >= 1");
  if (substeps < 1 || substeps > 100) throw std::invalid_argument("parameter 'substeps' must be in [1, 100]");
  if (pbf_iterations < 1 || pbf_iterations > 100) {
    throw std::invalid_argument("parameter 'pbf_iterations' must be in [1, 100]");
  }
  requireFinite(pbf_density_tolerance, "pbf_density_tolerance");
  if (pbf_density_tolerance < 0.0) throw std::invalid_argument("parameter 'pbf_density_tolerance' must be >= 0");
  if (pbf_max_iterations < 1 || pbf_max_iterations > 100) {
    throw std::invalid_argument("parameter 'pbf_max_iterations' must be in [1, 100]");
  }
  requirePositive(pbf_relaxation, "pbf_relaxation");
  requirePositive(pbf_omega, "pbf_omega");
  if (pbf_omega > 1.0) throw std::invalid_argument("parameter 'pbf_omega' must be in (0, 1]");
  requireFinite(pbf_tensile_k, "pbf_tensile_k");
  if (pbf_tensile_k < 0.0) throw std::invalid_argument("parameter 'pbf_tensile_k' must be >= 0");
  requirePositive(pbf_tensile_dq, "pbf_tensile_dq");
  if (pbf_tensile_dq >= 1.0) throw std::invalid_argument("parameter 'pbf_tensile_dq' must be < 1");
  if (pbf_tensile_n < 1 || pbf_tensile_n > 8)
    throw std::invalid_argument("parameter 'pbf_tensile_n' must be in [1, 8]");
  requireFinite(xsph_viscosity, "xsph_viscosity");
  if (xsph_viscosity < 0.0 || xsph_viscosity > 1.0) {
    throw std::invalid_argument("parameter 'xsph_viscosity' must be in [0, 1]");
  }
  requireFinite(vorticity_confinement, "vorticity_confinement");
  if (vorticity_confinement < 0.0) throw std::invalid_argument("parameter 'vorticity_confinement' must be >= 0");
  requirePositive(cfl, "cfl");
  if (cfl > 1.0) throw std::invalid_argument("parameter 'cfl' must be <= 1");
  if (max_substeps < 1 || max_substeps > 1000) {
    throw std::invalid_argument("parameter 'max_substeps' must be in [1, 1000]");
  }
  requirePositive(density_tolerance, "density_tolerance");
  requirePositive(divergence_tolerance, "divergence_tolerance");
  if (max_iterations < 1 || max_iterations > 10000) {
    throw std::invalid_argument("parameter 'max_iterations' must be in [1, 10000]");
  }
}

SimParams thesisPreset() { return SimParams{}; }

namespace {

// What pbf and dfsph share: the thesis's water, masses and frame; the cubic spline with a support
// of two lattice spacings for both classes (x = 4/3 pi 2^3 kernel particles: about 33 neighbours,
// and a resting lattice sums to rho0 exactly); no surface tension (the thesis's colour-field force
// at this resolution is an artefact, not water's); the walls in the density (boundary_volume.h).
SimParams incompressibleBase(const char* name) {
  SimParams p;
  p.preset = name;
  p.solver = name;
  p.kernel_particles_small = 4.0 / 3.0 * std::numbers::pi * 8.0;
  p.kernel_particles_large = p.kernel_particles_small;
  p.surface_tension_enabled = false;
  p.viscosity = 0.0;  // XSPH smooths the velocities instead
  return p;
}

}  // namespace

SimParams pbfPreset() {
  SimParams p = incompressibleBase("pbf");
  // Four solver steps of 2.5 ms a frame: each step starts from zero multipliers (pbf_solver.cpp),
  // and the compression a deep tank keeps at rest falls with dt^2; with two steps it is about 2 %,
  // with four about 0.5 %. Two iterations a step at a relaxation of 0.65 hold the tank and the
  // dam-break front as three at 0.5 did, in two thirds of the passes; at 0.85 the tank did not
  // come to rest, at 1 it blew up (docs/fluids.md).
  p.substeps = 4;
  p.pbf_iterations = 2;
  p.pbf_omega = 0.65;
  // No artificial pressure: MM13 add it against the clumping that negative pressure causes (the
  // tensile instability), but lambda <= 0 here (pbf_passes.h) already never pulls; at rest it
  // would be a stiff attraction, s_corr l_c is the same displacement whatever dt, that keeps a
  // tank jittering at several cm/s.
  p.pbf_tensile_k = 0.0;
  // XSPH a little stronger than the base's 0.01 a step: smoothed once a frame (velocity_passes.h,
  // xsphOfFrame) instead of every step, 0.01 left the validation tank less calm than before, 0.015
  // calmer, the fronts the same (docs/fluids.md).
  p.xsph_viscosity = 0.015;
  // No vorticity confinement (MM13 eq. 16) either: it puts back rotation that a coarse solver
  // damps, but at this resolution the Martin & Moyce front and the resting tank are the same
  // with it and without (docs/fluids.md), and its pass was an eighth of every step. A scene that
  // wants it sets `vorticity_confinement`.
  p.vorticity_confinement = 0.0;
  // Deep water (the Martin & Moyce column, 48 layers) keeps several per cent of compression with
  // 3 iterations: past them a step iterates on to 1 % (docs/fluids.md).
  p.pbf_density_tolerance = 0.01;
  return p;
}

SimParams dfsphPreset() {
  SimParams p = incompressibleBase("dfsph");
  // Solver steps of at most 5 ms (SPlisHSPlasH's ceiling): in 10 ms steps a tank at rest kept
  // sloshing at 0.1-0.5 m/s; in 5 ms steps it comes to rest (docs/fluids.md).
  p.substeps = 2;
  // A tank released from its lattice sloshes for seconds: with c = 0.01 it came below 5 mm/s
  // after about 6 s, with 0.05 after 2 s (smoothed every step; smoothed once a frame, 0.06 keeps
  // it as calm); the divergence solve's tolerance sets the speed it keeps at rest (up to 4.7 mm/s
  // at 1e-3, 1.3-2.3 at 1e-4, about 3 at 3e-4) and, where the water moves, its cost: 3e-4 takes a
  // third of 1e-4's divergence iterations on the dam break, with the same front and the held
  // column as still (docs/performance.md).
  p.xsph_viscosity = 0.06;
  p.divergence_tolerance = 3e-4;
  // Conjugate gradients past the first Jacobi iterations: the validation tank comes to rest
  // (under Jacobi alone its interior kept stirring at about 5 mm/s) and the held dam-break
  // column takes half the iterations (docs/fluids.md).
  p.conjugate_gradients = true;
  return p;
}

const std::vector<std::string>& presetNames() {
  static const std::vector<std::string> names = {"thesis", "pbf", "dfsph"};
  return names;
}

bool presetByName(const std::string& name, SimParams& out) {
  if (name == "thesis") {
    out = thesisPreset();
  } else if (name == "pbf") {
    out = pbfPreset();
  } else if (name == "dfsph") {
    out = dfsphPreset();
  } else {
    return false;
  }
  return true;
}

}  // namespace sph
