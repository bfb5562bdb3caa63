// AVX-512 forms of the two pair-sum stages of fluid_stages.h: 16 neighbours per instruction, the
// neighbour attributes gathered by index, batches running on from one particle's list into the
// next's. Each particle still sums its own neighbours in list order (lane sums, then one fixed
// horizontal reduction) and which lanes they take depends only on the lists' layout, so the
// result does not depend on the thread count. Internal to the library: callers use sph::computeDensityPressure and
// sph::computeAccelerations, which pick this code where the build targets AVX-512.
#pragma once

#if defined(__AVX512F__) && !defined(SPH_SCALAR_FLUID)
#define SPH_AVX512_FLUID 1

#include "sph/fluid_stages.h"

namespace sph::avx512 {

void computeDensityPressure(const SimParams& params, const KernelTable& kernels, const NeighborGrid& grid,
                            ParticleSet& particles);

void computeAccelerations(const SimParams& params, const KernelTable& kernels, const NeighborGrid& grid,
                          ParticleSet& particles, bool propagate_surface_distance);

}  // namespace sph::avx512

#endif
