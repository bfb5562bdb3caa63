// The solid's share of a fluid particle's kernel, so that walls and obstacles count in its density
// and push it with the pressure the incompressible solvers compute (pbf, dfsph):
//   Phi(x) = sum over the wall's virtual particles b of V W(|x - x_b|, h),   rho_wall = rho0 Phi,
// the boundary particles of Akinci et al. 2012 placed on the continuation of each class's rest
// lattice into the solid (layers at half a spacing and on behind each wall, shells inside each
// obstacle), and summed rather than stored: each layer (each row along an edge) is summed over
// the lattice's own in-plane points, for a particle on a lattice column, so a face
// is a function of the distance alone, an edge of two and a corner of three (inclusion and
// exclusion of the three near faces). In the spirit of the volume maps of Bender et al. 2019, but
// layered like the fluid: a particle of a resting lattice at a wall then sees exactly the density
// and the density gradient of the interior (a continuous wall integral gives the first layer 4 %
// too much density and 20 % too little gradient; integrating only along the layers still leaves
// 2 % of the gradient, which the pressure force multiplies by the absolute pressure). Obstacle and box volumes are
// added, so where an obstacle meets the floor the overlap counts twice (a thin band of extra density along the joint).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "sph/boundary.h"
#include "sph/kernels.h"
#include "sph/params.h"
#include "sph/particles.h"

namespace sph {

// Phi and its gradient at one point, and the part of d(rho_wall)/dt that the solid's own motion
// makes: grad Phi . v_solid (only moving walls of the box move).
struct BoundarySample {
  float phi = 0.0f;
  Vec3 grad = Vec3::Zero();
  float grad_dot_wall_velocity = 0.0f;
};

class BoundaryVolume {
 public:
  // `spacing[c]`: the rest lattice spacing of class c, cbrt(m / rho0), of the virtual particles.
  BoundaryVolume(const Boundary& boundary, const std::array<CubicKernel, kMaxLevels>& kernels,
                 const std::array<float, kMaxLevels>& spacing, int levels);

  // Phi, grad Phi at x for a particle of class c, with the box as it stands at this instant.
  BoundarySample sample(const Vec3& x, int class_index, const BoxState& box) const;

 private:
  // A 1D table of a function of distance and its derivative, linear between samples.
  struct Table {
    float start = 0.0f, inv_step = 0.0f;
    std::vector<float> value, slope;
    void at(float x, float& v, float& dv) const;
  };
  // The box's part: the faces, edges and corner within reach, from distances to the nearest face
  // on each axis (in metres) and which face (min: sign +1, max: -1).
  void boxShare(const float distance[3], const float sign[3], int c, BoundarySample& out) const;

  std::array<CubicKernel, kMaxLevels> kernels_;
  std::array<float, kMaxLevels> spacing_{};
  std::array<Table, kMaxLevels> plane_, line_;  // A(u): a layer's integral; L(rho): a row's
  std::array<Table, kMaxLevels> face_;          // a face's layers at distance d: s sum_l A(d + (l + 1/2) s)
  std::vector<std::array<Table, kMaxLevels>> spheres_, cylinders_;  // Phi(D) per obstacle
  std::vector<float> sphere_radius_, cylinder_radius_;
  std::vector<Eigen::Vector3f> sphere_centres_;
  std::vector<Eigen::Vector2f> cylinder_axes_;  // x, z
};

}  // namespace sph
