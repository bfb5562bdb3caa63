#include "sph/solvers/thesis/thesis_stages.h"

#include <cmath>
#include <limits>

#include "sph/collision.h"
#include "sph/simd/simd_level.h"
#include "sph/solvers/thesis/coincident_pairs.h"
#include "sph/solvers/thesis/thesis_stage_ends.h"
#include "sph/thread_share.h"

namespace sph {

KernelTable makeKernelTable(const SimParams& params) {
  const auto classes = params.levelProps();
  KernelTable table;
  for (int c = 0; c < kMaxLevels; ++c) table[c] = KernelConstants::forSupport(classes[c].support);
  return table;
}

void computeDensityPressure(const SimParams& params, const KernelTable& kernels, const NeighborGrid& grid,
                            ParticleSet& particles) {
  thesisStageForms().computeDensityPressure(params, kernels, grid, particles);
}

void computeAccelerations(const SimParams& params, const KernelTable& kernels, const NeighborGrid& grid,
                          ParticleSet& particles, bool propagate_surface_distance) {
  thesisStageForms().computeAccelerations(params, kernels, grid, particles, propagate_surface_distance);
}

ThesisStageForms thesisStageForms() {
  return formsForThisCpu(scalar::thesisStageForms, avx2::thesisStageForms, avx512::thesisStageForms);
}

ThesisStageForms scalar::thesisStageForms() {
  return {scalar::computeDensityPressure, scalar::computeAccelerations, scalar::integrateInBareBox};
}

namespace scalar {

void computeDensityPressure(const SimParams& params, const KernelTable& kernels, const NeighborGrid& grid,
                            ParticleSet& p) {
  const float rho0 = static_cast<float>(params.rest_density);
  const float k = static_cast<float>(params.gas_stiffness);
  const std::size_t n = p.size();
#pragma omp parallel for schedule(dynamic, kPairLoopChunk)
  for (std::size_t i = 0; i < n; ++i) {
    const KernelConstants& ki = kernels[levelIndex(p.level[i])];
    const Vec3 xi = p.position[i];
    float rho = p.mass[i] * poly6(ki, 0.0f);  // the particle's own contribution (j = i)
    for (std::uint32_t j : grid.neighbors(i)) {
      const float r2 = (xi - p.position[j]).squaredNorm();
      float w = poly6(ki, r2);
      if (p.level[j] != p.level[i]) {
        w = 0.5f * (w + poly6(kernels[levelIndex(p.level[j])], r2));  // eq. (3.35)
      }
      rho += p.mass[j] * w;  // eq. (3.11)
    }
    storeDensity(p, i, rho, k, rho0);
  }
}

void computeAccelerations(const SimParams& params, const KernelTable& kernels, const NeighborGrid& grid, ParticleSet& p,
                          bool propagate_surface_distance) {
  const ForceConstants constants(params);
  const std::size_t n = p.size();

#pragma omp parallel for schedule(dynamic, kPairLoopChunk)
  for (std::size_t i = 0; i < n; ++i) {
    const Level ci = p.level[i];
    const KernelConstants& ki = kernels[levelIndex(ci)];
    const Vec3 xi = p.position[i];
    const Vec3 ui = p.velocity[i];
    const float pi_over_rho2 = p.pressure_term[i];

    Vec3 pressure_acc = Vec3::Zero();  // f_pressure / rho_i
    Vec3 viscous = Vec3::Zero();       // f_viscosity / mu
    Vec3 normal = Vec3::Zero();        // n = grad c, eq. (3.17)
    // The colour field sums over every j including i (3.16); only the Laplacian has a self term.
    float colour_laplacian = p.volume[i] * poly6Laplacian(ki, 0.0f);
    float surface_hop = std::numeric_limits<float>::infinity();

    for (std::uint32_t j : grid.neighbors(i)) {
      const Vec3 r = xi - p.position[j];
      const float r2 = r.squaredNorm();
      const float rl = std::sqrt(r2);
      const float inv_r = rl > 0.0f ? 1.0f / rl : 0.0f;
      float spiky = spikyGradFactor(ki, rl, inv_r);
      float visc = viscosityLaplacian(ki, rl);
      float cgrad = poly6GradFactor(ki, r2);
      float clap = poly6Laplacian(ki, r2);
      if (p.level[j] != ci) {
        // Averaged kernels, eq. (3.35): the pair sees the same kernel from both sides.
        const KernelConstants& kj = kernels[levelIndex(p.level[j])];
        spiky = 0.5f * (spiky + spikyGradFactor(kj, rl, inv_r));
        visc = 0.5f * (visc + viscosityLaplacian(kj, rl));
        cgrad = 0.5f * (cgrad + poly6GradFactor(kj, r2));
        clap = 0.5f * (clap + poly6Laplacian(kj, r2));
      }
      const float volj = p.volume[j];
      // Pressure, eq. (3.13) divided by rho_i: symmetric in i and j, so momentum is conserved.
      if (r2 > 0.0f) {
        pressure_acc -= (p.mass[j] * (pi_over_rho2 + p.pressure_term[j]) * spiky) * r;
      } else {
        pressure_acc += coincidentPressureAcceleration(p, kernels, i, j);
      }
      // Viscosity, eq. (3.14).
      viscous += (volj * visc) * (p.velocity[j] - ui);
      // Colour field gradient and Laplacian, eqs. (3.16)-(3.18).
      normal += (volj * cgrad) * r;
      colour_laplacian += volj * clap;
      if (propagate_surface_distance) surface_hop = std::min(surface_hop, p.surface_distance[j] + rl);
    }

    storeAcceleration(p, i, {pressure_acc, viscous, normal, colour_laplacian}, constants);
    if (propagate_surface_distance) p.surface_hop[i] = surface_hop;
  }
}

}  // namespace scalar

namespace scalar {
#include "sph/solvers/thesis/bare_box_integration.inc"
}  // namespace scalar

void integrateAndCollide(const SimParams& params, const Boundary& boundary, const BoxState& box, ParticleSet& p) {
  const float dt = static_cast<float>(params.time_step);
  const std::size_t n = p.size();
  if (boundary.spheres.empty() && boundary.cylinders.empty()) {
    const float* acceleration = p.acceleration.data()->data();
    const float* radius = p.radius.data();
    float* velocity = p.velocity.data()->data();
    float* position = p.position.data()->data();
    const auto integrate = thesisStageForms().integrateInBareBox;
#pragma omp parallel
    {
      const ThreadShare share = threadShare(n);
      integrate(dt, box, share.begin, share.end, acceleration, radius, velocity, position);
    }
    return;
  }
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    Vec3 u = p.velocity[i] + dt * p.acceleration[i];  // eq. (3.21)
    Vec3 x = p.position[i] + dt * u;                  // eq. (3.22), with the updated velocity
    const float r = p.radius[i];
    collideBoundary(boundary, box, r, x, u);
    p.velocity[i] = u;
    p.position[i] = x;
  }
}

}  // namespace sph
