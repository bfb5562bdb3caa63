#include "sph/params.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sph {

const char* levelName(Level c) {
  static const char* const kNames[kMaxLevels] = {"L0", "L1", "L2", "L3", "L4", "L5", "L6", "L7"};
  const int k = levelIndex(c);
  return k >= 0 && k < kMaxLevels ? kNames[k] : "L?";
}

namespace {

LevelProps deriveClass(double mass, double kernel_particles, double rho0) {
  LevelProps p;
  p.mass = mass;
  p.kernel_particles = kernel_particles;
  p.radius = std::cbrt(3.0 * mass / (4.0 * std::numbers::pi * rho0));  // (3.7)
  const double volume = mass / rho0;
  p.support = std::cbrt(3.0 * volume * kernel_particles / (4.0 * std::numbers::pi));  // (3.8)
  return p;
}

}  // namespace

std::array<LevelProps, kMaxLevels> SimParams::levelProps() const {
  std::array<LevelProps, kMaxLevels> props;
  props[0] = deriveClass(mass_small, kernel_particles_small, rest_density);
  for (int k = 1; k < kMaxLevels; ++k) {
    props[static_cast<std::size_t>(k)] =
        deriveClass(std::ldexp(mass_large, k - 1), kernel_particles_large, rest_density);
  }
  return props;
}

double SimParams::surfaceThreshold() const { return std::sqrt(rest_density / kernel_particles_large); }

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
  // Four solver steps a frame: each step starts from zero multipliers (pbf_solver.cpp), and the
  // compression a deep tank keeps at rest falls with dt^2. Two iterations a step at a relaxation of
  // 0.65 hold the tank and the dam-break front as three at 0.5 do, in two thirds of the passes; a
  // larger relaxation keeps the tank from coming to rest (docs/fluids.md).
  p.substeps = 4;
  p.pbf_iterations = 2;
  p.pbf_omega = 0.65;
  // No artificial pressure: MM13 add it against the clumping that negative pressure causes (the
  // tensile instability), but lambda <= 0 here (pbf_passes.h) already never pulls; at rest it
  // would be a stiff attraction (s_corr is the same displacement whatever dt) that keeps a tank
  // jittering.
  p.pbf_tensile_k = 0.0;
  // XSPH is applied once a frame (velocity_passes.h, xsphOfFrame) rather than every step: a
  // little more than the base's smoothing keeps the validation tank as calm, the fronts the same.
  p.xsph_viscosity = 0.015;
  // No vorticity confinement (MM13 eq. 16): at this resolution the Martin & Moyce front and the
  // resting tank are the same with it and without, and its pass costs every step. A scene that
  // wants it sets `vorticity_confinement`.
  p.vorticity_confinement = 0.0;
  // Deep water (the Martin & Moyce column) keeps several per cent of compression with the least
  // iterations: past them a step iterates on to 1 %.
  p.pbf_density_tolerance = 0.01;
  return p;
}

SimParams dfsphPreset() {
  SimParams p = incompressibleBase("dfsph");
  // Solver steps of at most 5 ms (SPlisHSPlasH's ceiling): in 10 ms steps a tank at rest keeps
  // sloshing (docs/fluids.md).
  p.substeps = 2;
  // A tank released from its lattice sloshes for seconds; stronger XSPH (once a frame) brings it to
  // rest sooner. The divergence solve's tolerance sets the speed the water keeps at rest and,
  // where it moves, the solve's cost: this one keeps the front and the held column as a tighter
  // one does, in a third of the divergence iterations.
  p.xsph_viscosity = 0.06;
  p.dfsph_divergence_tolerance = 3e-4;
  // Conjugate gradients past the first Jacobi iterations: the validation tank comes to rest
  // (under Jacobi alone its interior keeps stirring) and the held dam-break column takes about
  // half the iterations (docs/fluids.md).
  p.dfsph_conjugate_gradients = true;
  return p;
}

std::vector<std::string> presetOrSceneNames() {
  std::vector<std::string> names = presetNames();
  names.emplace_back("scene");
  return names;
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
