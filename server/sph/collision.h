// Collision detection and response, eqs. (3.23)-(3.32). Each function moves a penetrating particle
// to the contact point (3.31), its radius taken into account, and removes the component of its
// velocity relative to the surface that points into the surface (3.32; for moving walls the
// velocity relative to the wall). Returns true on contact.
#pragma once

#include "sph/boundary.h"
#include "sph/particles.h"

namespace sph {

// Sphere obstacle, eqs. (3.25)-(3.28), inflated by the particle radius.
bool collideSphere(const Sphere& sphere, float particle_radius, Vec3& x, Vec3& u);

// Vertical cylinder from floor to roof (thesis 3.5.2): the sphere test in the x-z plane.
bool collideCylinder(const Cylinder& cylinder, float particle_radius, Vec3& x, Vec3& u);

// Inside of the axis-aligned box, eqs. (3.29)-(3.30), with wall velocities for moving walls.
bool collideBox(const BoxState& box, float particle_radius, Vec3& x, Vec3& u);

}  // namespace sph
