// The cubic kernels of the incompressible solvers' pairs: each class's own, and the one a mixed
// SMALL-LARGE pair shares, of the mean support (h_i + h_j) / 2, where the thesis averages both
// classes' kernels (3.35); pair_kernel.inc says why. Its support is the neighbour lists' reach,
// eq. (3.34), so no pair is cut short.
#pragma once

#include <array>
#include <cstddef>

#include "sph/kernels.h"
#include "sph/params.h"

namespace sph {

struct PairKernels {
  std::array<CubicKernel, kSizeClassCount> classes{};
  CubicKernel mixed;
  // Each class's particle mass: every particle of a class has it (split and merge keep it so), and
  // a pair pass knows a neighbour's class from the support it reads for the mixed pairs' kernel,
  // so it takes the neighbour's mass from here instead of gathering it (pair_kernel.inc).
  std::array<float, kSizeClassCount> mass{};

  CubicKernel& operator[](std::size_t c) { return classes[c]; }
  const CubicKernel& operator[](std::size_t c) const { return classes[c]; }

  // Each class's kernel of the given support and its mass, and the mixed pairs' kernel. The
  // supports must differ: a pass tells the classes apart by them.
  static PairKernels forClasses(const std::array<double, kSizeClassCount>& support,
                                const std::array<double, kSizeClassCount>& mass) {
    PairKernels k;
    for (std::size_t c = 0; c < k.classes.size(); ++c) {
      k.classes[c] = CubicKernel::forSupport(support[c]);
      k.mass[c] = static_cast<float>(mass[c]);
    }
    k.mixed = CubicKernel::forSupport(0.5 * (support[0] + support[1]));
    return k;
  }
};

}  // namespace sph
