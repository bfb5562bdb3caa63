// The per-particle ends of the two pair-sum stages, shared by the scalar loops (thesis_stages.cpp)
// and the AVX2 and AVX-512 loops (thesis_stages.inc): what a particle does with its sums.
#pragma once

#include <cstddef>

#include "sph/params.h"
#include "sph/particles.h"

namespace sph {

// Density, pressure (eq. (3.12)) and the per-particle factors the force loop reads.
inline void storeDensity(ParticleSet& p, std::size_t i, float rho, float gas_stiffness, float rest_density) {
  const float pressure = gas_stiffness * (rho - rest_density);
  p.density[i] = rho;
  p.pressure[i] = pressure;
  p.pressure_term[i] = pressure / (rho * rho);
  p.volume[i] = p.mass[i] / rho;
}

// One particle's pair sums in the force loop.
struct ForceSums {
  Vec3 pressure_acc;       // f_pressure / rho_i, eq. (3.13)
  Vec3 viscous;            // f_viscosity / mu, eq. (3.14)
  Vec3 normal;             // n = grad c, eq. (3.17)
  float colour_laplacian;  // lap c, eq. (3.18), self term included
};

// The stage's constants, read once from the parameters.
struct ForceConstants {
  float mu, sigma, threshold;
  bool tension;
  Vec3 gravity;

  explicit ForceConstants(const SimParams& params)
      : mu(static_cast<float>(params.viscosity)),
        sigma(static_cast<float>(params.surface_tension)),
        threshold(static_cast<float>(params.surfaceThreshold())),
        tension(params.surface_tension_enabled && params.surface_tension > 0.0),
        gravity(0.0f, static_cast<float>(params.gravity), 0.0f) {}
};

// Acceleration a = F / rho and |n| from the sums.
inline void storeAcceleration(ParticleSet& p, std::size_t i, const ForceSums& s, const ForceConstants& c) {
  const float rhoi = p.density[i];
  Vec3 acc = s.pressure_acc + (c.mu / rhoi) * s.viscous + c.gravity;  // gravity: f = rho g, eq. (3.15)
  const float normal_len = s.normal.norm();
  if (c.tension && normal_len >= c.threshold) {
    // Surface tension, eq. (3.19): f = -sigma lap(c) n / |n|, applied where |n| >= l (3.36).
    acc += (-c.sigma * s.colour_laplacian / (normal_len * rhoi)) * s.normal;
  }
  p.acceleration[i] = acc;
  p.normal_length[i] = normal_len;
}

}  // namespace sph
