// The fluid's container and obstacles, and how they change over time: an axis-aligned box whose
// bounds may jump at set times (the dam-break expansion), walls of that box that oscillate (the wave
// generator), spheres, and vertical cylinders from floor to roof (thesis 3.5, 4.2).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace sph {

struct Aabb {
  Eigen::Vector3d min = Eigen::Vector3d::Zero();
  Eigen::Vector3d max = Eigen::Vector3d::Zero();

  bool contains(const Eigen::Vector3d& p) const {
    return (p.array() >= min.array()).all() && (p.array() <= max.array()).all();
  }
  void expandToInclude(const Aabb& other) {
    min = min.cwiseMin(other.min);
    max = max.cwiseMax(other.max);
  }
};

// At `time` the box takes the bounds `box` (a dam-break box that opens, for example).
struct BoxChange {
  double time = 0.0;
  Aabb box;
};

// One side of the box moves as offset(t) = amplitude * (1 - cos(2 pi (t - start) / period)) / 2 for
// t >= start: it starts at rest and moves smoothly out and back. A negative amplitude moves the
// side towards -axis.
struct MovingWall {
  int axis = 0;           // 0 x, 1 y, 2 z
  bool max_side = false;  // which face of the box along `axis`
  double amplitude = 0.0;
  double period = 1.0;
  double start_time = 0.0;

  double offset(double t) const;
  double velocity(double t) const;
};

struct Sphere {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0.0;
};

// Vertical cylinder from the floor to the roof of the box (thesis 3.5.2): only x, z of the axis.
struct Cylinder {
  double x = 0.0;
  double z = 0.0;
  double radius = 0.0;
};

// The box's faces and their velocities at one instant, in float for the collision loop.
struct BoxState {
  Eigen::Vector3f min = Eigen::Vector3f::Zero();
  Eigen::Vector3f max = Eigen::Vector3f::Zero();
  Eigen::Vector3f min_velocity = Eigen::Vector3f::Zero();
  Eigen::Vector3f max_velocity = Eigen::Vector3f::Zero();
};

struct Boundary {
  Aabb box;                        // bounds at t = 0
  std::vector<BoxChange> changes;  // sorted by time
  std::vector<MovingWall> moving_walls;
  std::vector<Sphere> spheres;
  std::vector<Cylinder> cylinders;

  BoxState stateAt(double t) const;
  // A box that holds the container at every instant: sizes the neighbour grid once.
  Aabb enclosingBox() const;
};

}  // namespace sph
