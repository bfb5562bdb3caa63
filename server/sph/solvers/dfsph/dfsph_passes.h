// The pair passes of divergence-free SPH (Bender & Koschier 2015, 2017, "BK17", in the form of
// SPlisHSPlasH's current DFSPH: a relaxed Jacobi solve for the pressure, here optionally sped up
// by conjugate gradients), one form per instruction set (simd_level.h), the same source for both
// (dfsph_passes.inc); dfsph_solver.cpp and dfsph_conjugate_gradients.cpp run the solves with
// them. With the walls' volume Phi (boundary_volume.h), k = p / rho^2:
//   density       rho_i = sum_j m_j W_ij + rho0 Phi_i, and the inverse Jacobi diagonal
//                 1 / (|G + B|^2 + m_i sum_j m_j |grad W_ij|^2),
//                 G = sum_j m_j grad W_ij, B = rho0 grad Phi_i (BK17 eq. 7's factor over rho)
//   change        D_i(u) = sum_j m_j (u_i - u_j) . grad W_ij + rho0 (u_i . grad Phi_i - rate_i):
//                 the density's rate of change under the velocity field u (rate_i: the moving
//                 wall's part, grad Phi . v_wall), or under accelerations (rate 0)
//   acceleration  a_i = -(sum_j m_j (k_i + k_j) grad W_ij + k_i rho0 grad Phi_i), the pressure's
//                 (thesis eq. (3.13)), the wall's virtual particles one-sided as Akinci et al.
//                 2012's in SPlisHSPlasH's DFSPH: they push with the particle's own k and carry
//                 none of their own, so the solve's system is the symmetric D(M^-1 D^T) of the
//                 fluid and the wall. Mirrored walls (k_b = k_i, with the hydrostatic rise below
//                 the particle after Band et al. 2018) hold a lattice at rest exactly, but the
//                 step gains energy from them: a deep column started at rest blew up from its
//                 floor within a few frames, while one-sided walls hold the tank (docs/fluids.md,
//                 "Walls that count").
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "sph/boundary_volume.h"
#include "sph/kernels.h"
#include "sph/neighbor_grid.h"
#include "sph/solvers/pair_kernels.h"
#include "sph/solvers/pair_vectors.h"

namespace sph {

struct DfsphArrays {
  std::size_t n = 0;
  const float* mass = nullptr;
  const float* support = nullptr;
  const std::uint8_t* class_index = nullptr;
  const float* position = nullptr;  // packed x, y, z
  float* density = nullptr;
  float* inverse_diagonal = nullptr;    // the density pass's
  float* boundary_grad = nullptr;       // grad Phi_i (packed)
  float* boundary_wall_rate = nullptr;  // grad Phi_i . v_wall
  // m_j grad W_ij of every pair, written by the density pass (pair_vectors.h): the positions
  // stay put through both solves, so their iterations read these.
  PairVectors pair_grad;
  const float* field = nullptr;      // the change pass's u (packed)
  bool with_wall_rate = true;        // subtract boundary_wall_rate (for velocities, not accelerations)
  float* change = nullptr;           // the change pass's result
  const float* stiffness = nullptr;  // k = p / rho^2, the acceleration pass's input
  float* acceleration = nullptr;     // the acceleration pass's result (packed)
};

struct DfsphConstants {
  PairKernels kernels;
  float rest_density = 0.0f;
  const BoundaryVolume* boundary = nullptr;
  BoxState box;
};

struct DfsphPassForms {
  void (*density)(const DfsphArrays&, const DfsphConstants&, const NeighborGrid&);
  void (*change)(const DfsphArrays&, const DfsphConstants&, const NeighborGrid&);
  void (*acceleration)(const DfsphArrays&, const DfsphConstants&, const NeighborGrid&);
};

namespace scalar {
DfsphPassForms dfsphPassForms();
}  // namespace scalar
namespace avx2 {
DfsphPassForms dfsphPassForms();
}  // namespace avx2
namespace avx512 {
DfsphPassForms dfsphPassForms();
}  // namespace avx512
// The forms this CPU runs (simd_level.h).
DfsphPassForms dfsphPassForms();

}  // namespace sph
