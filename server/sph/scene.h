// A scenario (thesis 4.2) as plain data: container and obstacles over time, where the water starts,
// how many particles, how long it runs and where the default camera looks. Scene files (JSON) are
// read into this by the scene loader (server/scene/); the library itself knows no file format.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>

#include "sph/adaptive/method.h"
#include "sph/boundary.h"
#include "sph/params.h"
#include "sph/particles.h"

namespace sph {

struct CameraSpec {
  Eigen::Vector3d eye{0.0, 1.0, 3.0};
  Eigen::Vector3d target{0.0, 0.0, 0.0};
  Eigen::Vector3d up{0.0, 1.0, 0.0};
  double fov_y_degrees = 45.0;
  int viewport_width = 1280;
  int viewport_height = 720;
  double near_plane = 0.05;
  double far_plane = 50.0;
};

struct Scene {
  std::string name;
  std::string source;  // file it was read from, for messages
  std::string description;
  SimParams params;
  Boundary boundary;
  // The water starts as a lattice filling this region from its floor up (so it is as shallow as
  // the region's footprint allows); the region need not be full.
  Aabb water;
  int large_particles = 10000;  // adaptive methods start with this many L1 particles
  int frames = 900;             // steps in a full-length run
  CameraSpec camera;
  // The method a run uses when none is named (regular, surface, gaze, hybrid), its settings, and
  // the gaze recording that drives gaze and hybrid headless (resolved against the scene's folder).
  std::string method = "regular";
  AdaptiveConfig adaptive;
  std::string gaze_recording;
};

// The scene with its container narrowed to the water region (clipped to the box) and nothing
// moving: where fresh water settles before it is released (Simulation's constructor).
Scene gatedScene(const Scene& scene);

// The particles a scene's water starts with, per level, when it starts at `start`: the mass of
// `large_particles` L1 particles, exactly. The regular method fills it with L0 (twice as many:
// 20,000 with the thesis preset), the thesis's adaptive methods with L1, and foveated with its
// coarsest level; where that level's mass does not divide the water's, the rest is one particle
// each of some finer levels (the binary digits of the remainder), so every start has the same mass.
std::array<int, kMaxLevels> initialFill(const Scene& scene, Level start);
// The fill's particles over all levels.
int initialParticleCount(const Scene& scene, Level start);
// Room for every particle of the scene's water at L0 (and at least ParticleSet::kDefaultCapacity):
// the particle capacity a run that may refine all its water needs.
std::size_t refinedCapacity(const Scene& scene);

}  // namespace sph
