// The pair passes of divergence-free SPH (Bender & Koschier 2015, 2017, "BK17", in the form of
// SPlisHSPlasH's current DFSPH: a relaxed Jacobi solve for the pressure), one form per
// instruction set (simd_level.h), the same source for both (dfsph_passes.inc); dfsph_solver.cpp
// runs its two solvers with them. With the walls' volume Phi (boundary_volume.h), k = p / rho^2:
//   density       rho_i = sum_j m_j W_ij + rho0 Phi_i, and the inverse Jacobi diagonal
//                 1 / ((G + 2 B) . (G + B) + m_i sum_j m_j |grad W_ij|^2),
//                 G = sum_j m_j grad W_ij, B = rho0 grad Phi_i (BK17 eq. 7's factor over rho, with
//                 the mirrored wall below; the wall does not move, so it adds to the first part only)
//   change        D_i(u) = sum_j m_j (u_i - u_j) . grad W_ij + rho0 (u_i . grad Phi_i - rate_i):
//                 the density's rate of change under the velocity field u (rate_i: the moving
//                 wall's part, grad Phi . v_wall), or under accelerations (rate 0)
//   acceleration  a_i = -(sum_j m_j (k_i + k_j) grad W_ij + 2 k_i rho0 grad Phi_i) - |g| M_i,
//                 the pressure's (thesis eq. (3.13); the wall's virtual particles carry the
//                 particle's own k, plus the hydrostatic rise with depth, Band et al. 2018's
//                 mirrored and extrapolated pressure: with Akinci's one-sided k_i the neighbours'
//                 pressure would push a wall particle into the wall, since its own k cancels out
//                 of its force; without the rise it would sink along a vertical wall). The
//                 extrapolation applies where the particle is under pressure (k_i > 0).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "sph/boundary_volume.h"
#include "sph/kernels.h"
#include "sph/neighbor_grid.h"

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
  float* boundary_moment = nullptr;     // the hydrostatic moment M_i (packed, boundary_volume.h)
  const float* field = nullptr;         // the change pass's u (packed)
  bool with_wall_rate = true;           // subtract boundary_wall_rate (for velocities, not accelerations)
  float* change = nullptr;              // the change pass's result
  const float* stiffness = nullptr;     // k = p / rho^2, the acceleration pass's input
  float* acceleration = nullptr;        // the acceleration pass's result (packed)
};

struct DfsphConstants {
  std::array<CubicKernel, kSizeClassCount> kernels;
  float rest_density = 0.0f;
  const BoundaryVolume* boundary = nullptr;
  // |g| for the constant-density solve (the wall's virtual pressure rises with depth like the
  // water's), 0 for the divergence solve (its k is no hydrostatic pressure).
  float hydrostatic_gravity = 0.0f;
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
namespace avx512 {
DfsphPassForms dfsphPassForms();
}  // namespace avx512

}  // namespace sph
