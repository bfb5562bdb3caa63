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

namespace sph {

using KernelTable = std::array<KernelConstants, kSizeClassCount>;

// Particles per chunk of the pair loops, which threads take as they come free: the cost of a
// particle varies with its class and neighbour count, and adaptive runs keep the costly SMALL
// particles together at the end of the arrays. Each particle's sums are its own, so the result
// does not depend on which thread takes which chunk.
inline constexpr int kPairLoopChunk = 256;

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

// The two pair-sum stages above, one pair at a time: the code of builds without AVX-512 and the
// reference the vector code is tested against (same sums; the vector code adds in another order
// and takes 1/|r| from a refined estimate, so results agree to float rounding, not bit for bit).
namespace scalar {
void computeDensityPressure(const SimParams& params, const KernelTable& kernels, const NeighborGrid& grid,
                            ParticleSet& particles);
void computeAccelerations(const SimParams& params, const KernelTable& kernels, const NeighborGrid& grid,
                          ParticleSet& particles, bool propagate_surface_distance = false);
}  // namespace scalar

// True when computeDensityPressure and computeAccelerations run 16 pairs per instruction
// (AVX-512 builds); false when they are the scalar forms.
bool fluidStagesVectorized();

// Semi-implicit Euler, eqs. (3.21)-(3.22), then collisions with obstacles and the box at `box`.
void integrateAndCollide(const SimParams& params, const Boundary& boundary, const BoxState& box,
                         ParticleSet& particles);

}  // namespace sph
