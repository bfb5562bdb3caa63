// The pair passes of position based fluids (Macklin & Mueller 2013, "MM13"), one form per
// instruction set (simd_level.h), the same source for both (pbf_passes.inc). pbf_solver.cpp
// orders them into a solver step.
//
// With particle masses m (two size classes), the density constraint of particle i is
//   C_i = rho_i / rho0 - 1,  rho_i = sum_j m_j W_ij + rho0 Phi_i         (MM13 eq. 1; Phi: walls)
// and a Jacobi iteration computes
//   dlambda_i = -C_i / (sum_k |grad_k C_i|^2 / m_k + eps)                      (MM13 eqs. 9-11)
// and moves every particle by
//   dx_i = 1 / (rho0 m_i) sum_j (dl_i m_j + dl_j m_i + s_ij (l_i m_j + l_j m_i) / 2) grad W_ij
//          + dl_i grad Phi_i / m_i                                              (MM13 eq. 12)
// the mass-weighted form of MM13's update (equal masses give theirs), which keeps sum m dx = 0:
// momentum is conserved pair by pair. The wall enters as Akinci et al. 2012's boundary particles
// do in a position-based solver: in C_i and in grad_i C_i, never moved, carrying no multiplier of
// their own (dx_i = grad_i C_i dl_i / m_i + the fluid neighbours' share). The correction is then
// M^-1 grad C^T dl, the projection position based dynamics rests on (a symmetric system);
// virtual particles that carry i's own dl as well ("mirrored") make it non-symmetric, and a
// resting tank gains energy from it. On a resting lattice sum_j m_j grad W_ij / rho0 + grad Phi_i
// vanishes at the walls too (boundary_volume.h), so the wall's share carries no absolute multiplier.
// Beyond MM13, lambda is the step's total multiplier,
// projected to lambda <= 0 (water pushes, never pulls: a particle below rest density keeps
// only what compression gave it, so the free surface does not clump), and dl is the change the
// projection allowed. s_ij = -k (W_ij / W(dq h))^n is MM13's artificial pressure (eq. 13) in
// units of l_c, the lambda of a full neighbourhood at C = 1, applied once a step with the first
// correction.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "sph/boundary_volume.h"
#include "sph/collision.h"
#include "sph/kernels.h"
#include "sph/neighbor_grid.h"
#include "sph/solvers/pair_kernels.h"

namespace sph {

// The per-particle arrays the passes read and write (packed x, y, z for vectors).
struct PbfArrays {
  std::size_t n = 0;
  const float* mass = nullptr;
  const float* support = nullptr;
  const std::uint8_t* class_index = nullptr;  // Level as 0 / 1
  float* position = nullptr;                  // predicted positions; the correction pass writes position_next
  float* position_next = nullptr;
  float* density = nullptr;      // rho_i of the last lambda pass
  float* lambda = nullptr;       // the step's total multiplier, <= 0
  float* lambda_step = nullptr;  // the change of lambda the correction pass applies
  // grad Phi_i at `position`, written by the lambda pass for the correction pass that follows it
  // at the same positions, so that the walls' volume is sampled once per iteration (packed)
  float* wall_grad = nullptr;
  // When set (NeighborGrid::slotCount() floats), the lambda pass keeps each pair's kernel gradient
  // factor g (grad W_ij = g r_ij) at the pair's slot (NeighborGrid::neighborSlot) and the
  // correction pass that follows it at the same positions reads it instead of evaluating the
  // kernel again; only where both visit every particle and the correction has no artificial
  // pressure (which needs W_ij as well). Null: the correction evaluates the kernel.
  float* pair_g = nullptr;
  // When set, a pass visits only these particles (in this order) and leaves the others' entries
  // as they are: the local iterations around freshly placed particles (pbf_solver.cpp).
  const std::uint32_t* only = nullptr;
  std::size_t only_count = 0;
  // When set, particle i's constraint holds it at rho0 + density_offset[i] instead of rho0 (a
  // level change in still water: pbf/still_water_changes.h).
  const float* density_offset = nullptr;
};

struct PbfConstants {
  PairKernels kernels;
  float rest_density = 0.0f;
  std::array<float, kMaxLevels> relaxation{};         // eps, absolute
  std::array<float, kMaxLevels> lambda_scale{};       // l_c: lambda of a full neighbourhood at C = 1
  std::array<float, kMaxLevels> tensile_reference{};  // W(dq h) per class
  float tensile_k = 0.0f;
  float omega = 1.0f;
  int tensile_n = 4;
  std::array<WallReach, kMaxLevels> contact{};  // nearest a centre may come to the walls
  const BoundaryVolume* boundary = nullptr;
  const Boundary* obstacles = nullptr;
  BoxState box;
};

// The pass functions of one form (the velocity passes are velocity_passes.h):
//   lambda   density, grad Phi and dlambda of every particle at `position`; lambda += dlambda projected to
//            <= 0, lambda_step = the change made
//   correct  position_next = position + dx from lambda_step (with the artificial pressure when
//            `tensile`), kept inside the box and out of the obstacles
struct PbfPassForms {
  void (*lambda)(const PbfArrays&, const PbfConstants&, const NeighborGrid&);
  void (*correct)(const PbfArrays&, const PbfConstants&, const NeighborGrid&, bool tensile);
};

namespace scalar {
PbfPassForms pbfPassForms();
}  // namespace scalar
namespace avx2 {
PbfPassForms pbfPassForms();
}  // namespace avx2
namespace avx512 {
PbfPassForms pbfPassForms();
}  // namespace avx512
// The forms this CPU runs (simd_level.h).
PbfPassForms pbfPassForms();

}  // namespace sph
