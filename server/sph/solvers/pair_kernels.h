// The cubic kernels of the incompressible solvers' pairs: each level's own, and for a pair of two
// levels the kernel of the mean support (h_i + h_j) / 2, where the thesis averages both classes'
// kernels (3.35); pair_kernel.inc says why and evaluates it lane by lane. Its support is the
// neighbour lists' reach, eq. (3.34), so no pair is cut short.
#pragma once

#include <array>
#include <cstddef>
#include <numbers>

#include "sph/kernels.h"
#include "sph/params.h"

namespace sph {

struct PairKernels {
  std::array<CubicKernel, kMaxLevels> classes{};

  // Tables a pass looks up by a neighbour's level (the level each list slot holds:
  // NeighborGrid::neighborLevels), 16 entries for a register of AVX-512 lanes, the first
  // kMaxLevels used. Every particle of a level has the level's mass and support (split and merge
  // keep it so), so a pair pass takes a neighbour's from here instead of gathering them
  // (pair_kernel.inc). For a particle of level i, the kernel of the mean support (h_i + h_j) / 2
  // of a pair with level j, in floats: 2 / (h_i + h_j), then sigma and the gradient's scale by the
  // products kernels.h defines, the bits a lane computing them would get.
  using LevelTable = std::array<float, 16>;
  static_assert(kMaxLevels <= 8, "the AVX2 lanes look up 8 entries");
  LevelTable mass{};
  LevelTable level_support{};
  std::array<LevelTable, kMaxLevels> mean_inv_h{};
  std::array<LevelTable, kMaxLevels> mean_sigma{};
  std::array<LevelTable, kMaxLevels> mean_grad_scale{};

  CubicKernel& operator[](std::size_t c) { return classes[c]; }
  const CubicKernel& operator[](std::size_t c) const { return classes[c]; }

  // Each level's kernel of its support and its mass. The supports must differ (SimParams::validate):
  // a pass tells the levels apart by them.
  static PairKernels forClasses(const std::array<LevelProps, kMaxLevels>& levels) {
    PairKernels k;
    for (std::size_t c = 0; c < k.classes.size(); ++c) {
      k.classes[c] = CubicKernel::forSupport(levels[c].support);
      k.mass[c] = static_cast<float>(levels[c].mass);
      k.level_support[c] = k.classes[c].h;
    }
    for (std::size_t i = 0; i < kMaxLevels; ++i) {
      for (std::size_t j = 0; j < kMaxLevels; ++j) {
        const float inv_h = 2.0f / (k.classes[i].h + k.classes[j].h);
        const float inv_h2 = inv_h * inv_h;
        k.mean_inv_h[i][j] = inv_h;
        k.mean_sigma[i][j] = static_cast<float>(8.0 / std::numbers::pi) * inv_h2 * inv_h;
        k.mean_grad_scale[i][j] = k.mean_sigma[i][j] * inv_h2;
      }
    }
    return k;
  }
};

}  // namespace sph
