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
  requirePositive(kernel_particles_small, "kernel_particles_small");
  requirePositive(kernel_particles_large, "kernel_particles_large");
  if (resort_interval < 1) throw std::invalid_argument("parameter 'resort_interval' must be >= 1");
}

SimParams thesisPreset() { return SimParams{}; }

bool presetByName(const std::string& name, SimParams& out) {
  if (name == "thesis") {
    out = thesisPreset();
    return true;
  }
  return false;
}

}  // namespace sph
