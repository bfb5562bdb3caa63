// The velocity passes the incompressible solvers share, one form per instruction set
// (simd_level.h), the same source for both (velocity_passes.inc):
//   smooth    XSPH (Macklin & Mueller 2013 eq. 17, after Schechter & Bridson 2012):
//             v_i + c sum_j V_j (v_j - v_i) W_ij into velocity_next; the vorticity
//             omega_i = sum_j V_j (v_i - v_j) x grad W_ij (MM13 eq. 15, the SPH curl); |n| of the
//             colour field n_i = sum_j V_j grad W_ij and the surface-distance hop, for the
//             adaptive step's surface criterion (3.44), (3.45); each of these three only where
//             its array is given (VelocityArrays: null skips it, at no cost)
//   confine   vorticity confinement (MM13 eq. 16): velocity_next += dt eps (N x omega_i),
//             N = eta / |eta|, eta = grad |omega| = sum_j V_j (|omega_j| - |omega_i|) grad W_ij
// V_j = m_j / rho_j.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "sph/kernels.h"
#include "sph/neighbor_grid.h"
#include "sph/solvers/pair_kernels.h"

namespace sph {

struct VelocityArrays {
  std::size_t n = 0;
  const float* support = nullptr;
  const std::uint8_t* class_index = nullptr;
  const float* position = nullptr;  // packed x, y, z
  const float* density = nullptr;
  const float* velocity = nullptr;
  float* velocity_next = nullptr;
  float* vorticity = nullptr;      // null: not computed (no confinement follows)
  float* normal_length = nullptr;  // null: |n| not computed (only the frame's last step's is read)
  const float* surface_distance = nullptr;
  float* surface_hop = nullptr;  // null: not computed (not tracked, or not the frame's last step)
};

struct VelocityConstants {
  PairKernels kernels;
  float dt = 0.0f;
  float xsph = 0.0f;
  float vorticity_epsilon = 0.0f;  // m/s: the confinement's acceleration is eps (N x omega)
};

// The XSPH coefficient of a frame's smoothing. Both solvers smooth once a frame, in its last step
// (whose pass also gives the adaptive step |n| and the hop), by as much as `steps` smoothings of c
// each leave of a velocity difference: 1 - (1 - c)^steps. So c keeps MM13's meaning, per solver
// step, and the smoothing per simulated second does not grow with the steps a CFL bound adds
// (docs/fluids.md, "XSPH once a frame").
inline float xsphOfFrame(double c, int steps) { return static_cast<float>(1.0 - std::pow(1.0 - c, steps)); }

struct VelocityPassForms {
  void (*smooth)(const VelocityArrays&, const VelocityConstants&, const NeighborGrid&);
  void (*confine)(const VelocityArrays&, const VelocityConstants&, const NeighborGrid&);
};

namespace scalar {
VelocityPassForms velocityPassForms();
}  // namespace scalar
namespace avx2 {
VelocityPassForms velocityPassForms();
}  // namespace avx2
namespace avx512 {
VelocityPassForms velocityPassForms();
}  // namespace avx512
// The forms this CPU runs (simd_level.h).
VelocityPassForms velocityPassForms();

}  // namespace sph
