// The per-step stages of the SPH fluid (thesis 3.3, 3.4, 3.5), each a parallel loop in which a
// particle reads its neighbours and writes only its own attributes: the result does not depend on
// the thread count. Kernels are the averaged kernels of eq. (3.35).
#pragma once

#include <array>

#include "sph/boundary.h"
#include "sph/kernels.h"
#include "sph/neighbor_grid.h"
#include "sph/params.h"
#include "sph/particles.h"
#include "sph/thread_share.h"

namespace sph {

using KernelTable = std::array<KernelConstants, kMaxLevels>;

KernelTable makeKernelTable(const SimParams& params);

// Density, eq. (3.11), and pressure, eq. (3.12).
void computeDensityPressure(const SimParams& params, const KernelTable& kernels, const NeighborGrid& grid,
                            ParticleSet& particles);

// Acceleration a = F / rho from pressure (3.13), viscosity (3.14), gravity (3.15) and surface
// tension (3.16)-(3.19) where |n| >= l (3.36). Also stores |n| per particle. With
// `propagate_surface_distance`, also one hop of the surface distance the adaptive step keeps:
// surface_hop[i] = min over neighbours j of surface_distance[j] + |r_ij| (fused here because this
// loop already has every pair's distance).
void computeAccelerations(const SimParams& params, const KernelTable& kernels, const NeighborGrid& grid,
                          ParticleSet& particles, bool propagate_surface_distance = false);

// The forms of the two pair-sum stages (simd_level.h): scalar, one pair at a time, the
// reference the vector code is tested against; AVX-512, 16 pairs per instruction (the same sums,
// added in another order, with 1/|r| from a refined estimate: results agree to float rounding,
// not bit for bit).
namespace scalar {
void computeDensityPressure(const SimParams& params, const KernelTable& kernels, const NeighborGrid& grid,
                            ParticleSet& particles);
void computeAccelerations(const SimParams& params, const KernelTable& kernels, const NeighborGrid& grid,
                          ParticleSet& particles, bool propagate_surface_distance = false);
}  // namespace scalar
namespace avx2 {
void computeDensityPressure(const SimParams& params, const KernelTable& kernels, const NeighborGrid& grid,
                            ParticleSet& particles);
void computeAccelerations(const SimParams& params, const KernelTable& kernels, const NeighborGrid& grid,
                          ParticleSet& particles, bool propagate_surface_distance = false);
}  // namespace avx2
namespace avx512 {
void computeDensityPressure(const SimParams& params, const KernelTable& kernels, const NeighborGrid& grid,
                            ParticleSet& particles);
void computeAccelerations(const SimParams& params, const KernelTable& kernels, const NeighborGrid& grid,
                          ParticleSet& particles, bool propagate_surface_distance = false);
}  // namespace avx512

// integrateAndCollide's loop for a box without obstacles, particles [begin, end) of packed x, y, z
// arrays; one form per instruction set (bare_box_integration.inc).
namespace scalar {
void integrateInBareBox(float dt, const BoxState& box, std::size_t begin, std::size_t end, const float* acceleration,
                        const float* radius, float* velocity, float* position);
}  // namespace scalar
namespace avx2 {
void integrateInBareBox(float dt, const BoxState& box, std::size_t begin, std::size_t end, const float* acceleration,
                        const float* radius, float* velocity, float* position);
}  // namespace avx2
namespace avx512 {
void integrateInBareBox(float dt, const BoxState& box, std::size_t begin, std::size_t end, const float* acceleration,
                        const float* radius, float* velocity, float* position);
}  // namespace avx512

// The thesis's stages as one form (simd_level.h).
struct ThesisStageForms {
  void (*computeDensityPressure)(const SimParams& params, const KernelTable& kernels, const NeighborGrid& grid,
                                 ParticleSet& particles);
  void (*computeAccelerations)(const SimParams& params, const KernelTable& kernels, const NeighborGrid& grid,
                               ParticleSet& particles, bool propagate_surface_distance);
  void (*integrateInBareBox)(float dt, const BoxState& box, std::size_t begin, std::size_t end,
                             const float* acceleration, const float* radius, float* velocity, float* position);
};
namespace scalar {
ThesisStageForms thesisStageForms();
}  // namespace scalar
namespace avx2 {
ThesisStageForms thesisStageForms();
}  // namespace avx2
namespace avx512 {
ThesisStageForms thesisStageForms();
}  // namespace avx512
// The forms this CPU runs.
ThesisStageForms thesisStageForms();

// Semi-implicit Euler, eqs. (3.21)-(3.22), then collisions with obstacles and the box at `box`.
void integrateAndCollide(const SimParams& params, const Boundary& boundary, const BoxState& box,
                         ParticleSet& particles);

}  // namespace sph
