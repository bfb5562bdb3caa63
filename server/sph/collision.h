// Collision detection and response, eqs. (3.23)-(3.32). Each function moves a penetrating particle
// to the contact point (3.31), its radius taken into account, and removes the component of its
// velocity relative to the surface that points into the surface (3.32; for moving walls the
// velocity relative to the wall). Returns true on contact.
//
// Inline: the integration calls them for every particle and obstacle each step, and out of line
// the calls (and the sphere's double centre converted to float each time) cost more than the test.
#pragma once

#include <cmath>

#include "sph/boundary.h"
#include "sph/particles.h"

namespace sph {

namespace detail {

// Removes the velocity component along the outward normal n when it points into the obstacle,
// eq. (3.32). A particle already moving away keeps its velocity.
inline void removeInwardVelocity(const Vec3& n, Vec3& u) {
  const float un = u.dot(n);
  if (un < 0.0f) u -= un * n;
}

}  // namespace detail

// Sphere obstacle, eqs. (3.25)-(3.28), inflated by the particle radius.
inline bool collideSphere(const Sphere& sphere, float particle_radius, Vec3& x, Vec3& u) {
  const Vec3 c = sphere.centre.cast<float>();
  const float reach = static_cast<float>(sphere.radius) + particle_radius;
  const Vec3 d = x - c;
  const float dist2 = d.squaredNorm();
  if (dist2 >= reach * reach) return false;  // F(x) >= 0, eq. (3.25)
  const float dist = std::sqrt(dist2);
  // Outward normal (3.28); a particle exactly at the centre is pushed up.
  const Vec3 n = dist > 0.0f ? Vec3(d / dist) : Vec3(0.0f, 1.0f, 0.0f);
  x = c + reach * n;  // contact point (3.26), response (3.31)
  detail::removeInwardVelocity(n, u);
  return true;
}

// Vertical cylinder from floor to roof (thesis 3.5.2): the sphere test in the x-z plane.
inline bool collideCylinder(const Cylinder& cylinder, float particle_radius, Vec3& x, Vec3& u) {
  const float reach = static_cast<float>(cylinder.radius) + particle_radius;
  const float dx = x.x() - static_cast<float>(cylinder.x);
  const float dz = x.z() - static_cast<float>(cylinder.z);
  const float dist2 = dx * dx + dz * dz;
  if (dist2 >= reach * reach) return false;
  const float dist = std::sqrt(dist2);
  const Vec3 n = dist > 0.0f ? Vec3(dx / dist, 0.0f, dz / dist) : Vec3(1.0f, 0.0f, 0.0f);
  x.x() = static_cast<float>(cylinder.x) + reach * n.x();
  x.z() = static_cast<float>(cylinder.z) + reach * n.z();
  detail::removeInwardVelocity(n, u);
  return true;
}

// How near a particle's centre may come to the box's floor (its lowest face) and to every other
// face and obstacle. One value for all of them (the thesis's particle radius, pbf's contact) converts
// implicitly; dfsph holds its floor further off than its sides (incompressible_setup.cpp).
struct WallReach {
  float floor = 0.0f;
  float sides = 0.0f;
  WallReach() = default;
  WallReach(float every_wall) : floor(every_wall), sides(every_wall) {}  // NOLINT(google-explicit-constructor)
  WallReach(float floor_reach, float side_reach) : floor(floor_reach), sides(side_reach) {}
};

// The planes a centre is kept between on axis a: the min face plus its reach (the floor's on the
// vertical axis), the max face less the sides'.
inline float guardLow(const BoxState& box, const WallReach& reach, int a) {
  return box.min[a] + (a == 1 ? reach.floor : reach.sides);
}
inline float guardHigh(const BoxState& box, const WallReach& reach, int a) { return box.max[a] - reach.sides; }

// Removes the part of u along axis a that moves into the min face (at_min) or the max face,
// relative to the face's own velocity, eq. (3.32).
inline void removeVelocityIntoFace(const BoxState& box, int a, bool at_min, Vec3& u) {
  if (at_min) {
    if (u[a] < box.min_velocity[a]) u[a] = box.min_velocity[a];
  } else if (u[a] > box.max_velocity[a]) {
    u[a] = box.max_velocity[a];
  }
}

// Inside of the axis-aligned box, eqs. (3.29)-(3.30), with wall velocities for moving walls.
inline bool collideBox(const BoxState& box, const WallReach& reach, Vec3& x, Vec3& u) {
  bool hit = false;
  for (int a = 0; a < 3; ++a) {
    const float lo = guardLow(box, reach, a);
    const float hi = guardHigh(box, reach, a);
    if (x[a] < lo) {
      // Contact point on the min face (3.29); normal +axis.
      x[a] = lo;
      removeVelocityIntoFace(box, a, true, u);
      hit = true;
    } else if (x[a] > hi) {
      x[a] = hi;
      removeVelocityIntoFace(box, a, false, u);
      hit = true;
    }
  }
  return hit;
}

// Every boundary in turn: the obstacles, then the box, so that whatever the obstacles did the
// particle ends inside the box.
inline void collideBoundary(const Boundary& boundary, const BoxState& box, const WallReach& reach, Vec3& x, Vec3& u) {
  for (const Sphere& s : boundary.spheres) collideSphere(s, reach.sides, x, u);
  for (const Cylinder& c : boundary.cylinders) collideCylinder(c, reach.sides, x, u);
  collideBox(box, reach, x, u);
}

}  // namespace sph
