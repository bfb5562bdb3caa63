// The cubic kernels of the incompressible solvers' pairs: each level's own, and for a pair of two
// levels the kernel of the mean support (h_i + h_j) / 2, where the thesis averages both classes'
// kernels (3.35); pair_kernel.inc says why and evaluates it lane by lane. Its support is the
// neighbour lists' reach, eq. (3.34), so no pair is cut short.
#pragma once

#include <array>
#include <cstddef>

#include "sph/kernels.h"
#include "sph/params.h"

namespace sph {

struct PairKernels {
  std::array<CubicKernel, kMaxLevels> classes{};
  // Each level's particle mass: every particle of a level has it (split and merge keep it so), so
  // a pair pass takes a neighbour's mass from here, by the neighbour's support where it is of
  // another level, instead of gathering it (pair_kernel.inc).
  std::array<float, kMaxLevels> mass{};
  // The run's levels (SimParams::levels): no particle is of a level at or past it.
  std::size_t count = kMaxLevels;

  CubicKernel& operator[](std::size_t c) { return classes[c]; }
  const CubicKernel& operator[](std::size_t c) const { return classes[c]; }

  // Each level's kernel of its support and its mass. The supports must differ (SimParams::validate):
  // a pass tells the levels apart by them.
  static PairKernels forClasses(const std::array<LevelProps, kMaxLevels>& levels, int count) {
    PairKernels k;
    k.count = static_cast<std::size_t>(count);
    for (std::size_t c = 0; c < k.classes.size(); ++c) {
      k.classes[c] = CubicKernel::forSupport(levels[c].support);
      k.mass[c] = static_cast<float>(levels[c].mass);
    }
    return k;
  }
};

}  // namespace sph
