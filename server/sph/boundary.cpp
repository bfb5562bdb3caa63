#include "sph/boundary.h"

#include <cmath>
#include <numbers>

namespace sph {

double MovingWall::offset(double t) const {
  if (t < start_time) return 0.0;
  const double phase = 2.0 * std::numbers::pi * (t - start_time) / period;
  return amplitude * 0.5 * (1.0 - std::cos(phase));
}

double MovingWall::velocity(double t) const {
  if (t < start_time) return 0.0;
  const double omega = 2.0 * std::numbers::pi / period;
  return amplitude * 0.5 * omega * std::sin(omega * (t - start_time));
}

BoxState Boundary::stateAt(double t) const {
  Aabb current = box;
  for (const BoxChange& change : changes) {
    if (change.time <= t) current = change.box;
  }
  BoxState s;
  s.min = current.min.cast<float>();
  s.max = current.max.cast<float>();
  for (const MovingWall& wall : moving_walls) {
    const float offset = static_cast<float>(wall.offset(t));
    const float velocity = static_cast<float>(wall.velocity(t));
    if (wall.max_side) {
      s.max[wall.axis] += offset;
      s.max_velocity[wall.axis] = velocity;
    } else {
      s.min[wall.axis] += offset;
      s.min_velocity[wall.axis] = velocity;
    }
  }
  return s;
}

Aabb Boundary::enclosingBox() const {
  Aabb all = box;
  for (const BoxChange& change : changes) all.expandToInclude(change.box);
  for (const MovingWall& wall : moving_walls) {
    // The offset sweeps [0, amplitude] (or [amplitude, 0]).
    const double reach = wall.amplitude;
    double& side = wall.max_side ? all.max[wall.axis] : all.min[wall.axis];
    if (wall.max_side) {
      side = std::max(side, side + reach);
    } else {
      side = std::min(side, side + reach);
    }
  }
  return all;
}

}  // namespace sph
