#include "sph/solvers/incompressible_setup.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sph/simd/simd_level.h"

namespace sph {

namespace {

// sum over the neighbours of a particle of a simple cubic lattice of |g(r) r|^2, g the gradient
// factor of the cubic spline (kernels.h).
double latticeGradSquared(const CubicKernel& k, double spacing) {
  const int reach = static_cast<int>(std::ceil(k.h / spacing));
  double sum = 0.0;
  for (int i = -reach; i <= reach; ++i) {
    for (int j = -reach; j <= reach; ++j) {
      for (int l = -reach; l <= reach; ++l) {
        if (i == 0 && j == 0 && l == 0) continue;
        const double r = spacing * std::sqrt(static_cast<double>(i * i + j * j + l * l));
        const double g = cubicGradFactor(k, static_cast<float>(r));
        sum += g * g * r * r;
      }
    }
  }
  return sum;
}

}  // namespace

IncompressibleSetup makeIncompressibleSetup(const Scene& scene, WallReach contact_spacings) {
  IncompressibleSetup s;
  const auto classes = scene.params.levelProps();
  s.kernels = PairKernels::forClasses(classes);
  for (int c = 0; c < kMaxLevels; ++c) {
    const auto cu = static_cast<std::size_t>(c);
    s.spacing[cu] = static_cast<float>(std::cbrt(classes[cu].mass / scene.params.rest_density));
    const float spacing = s.spacing[cu];
    s.contact[cu] = WallReach(contact_spacings.floor * spacing, contact_spacings.sides * spacing);
    s.lattice_grad_sq[cu] = s.kernels.mass[cu] * latticeGradSquared(s.kernels[cu], s.spacing[cu]);
  }
  s.boundary = std::make_unique<BoundaryVolume>(scene.boundary, s.kernels.classes, s.spacing, scene.params.levels);
  return s;
}

std::vector<float> restingPressure(const Scene& scene, const IncompressibleSetup& setup, const ParticleSet& p) {
  float top = -std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i < p.size(); ++i) {
    top = std::max(top, p.position[i].y() + 0.5f * setup.spacing[levelIndex(p.level[i])]);
  }
  const auto weight = static_cast<float>(scene.params.rest_density * std::abs(scene.params.gravity));
  std::vector<float> pressure(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) pressure[i] = weight * std::max(top - p.position[i].y(), 0.0f);
  return pressure;
}

VelocityArrays velocityArraysOf(ParticleSet& p, std::vector<Vec3>& velocity_next, std::vector<Vec3>& vorticity,
                                bool confinement, bool last_step, bool track_surface_distance) {
  VelocityArrays v;
  v.n = p.size();
  v.support = p.support.data();
  v.class_index = reinterpret_cast<const std::uint8_t*>(p.level.data());
  v.position = p.position.data()->data();
  v.density = p.density.data();
  v.velocity = p.velocity.data()->data();
  v.velocity_next = velocity_next.data()->data();
  v.vorticity = confinement ? vorticity.data()->data() : nullptr;
  v.normal_length = last_step ? p.normal_length.data() : nullptr;
  v.surface_distance = p.surface_distance.data();
  v.surface_hop = last_step && track_surface_distance ? p.surface_hop.data() : nullptr;
  return v;
}

int relaxAtRest(FluidSolver& solver, const FrameContext& frame, const IncompressibleSetup& setup, int max_frames) {
  ParticleSet& p = frame.particles;
  const float still = 1e-3f * std::min(setup.spacing[0], setup.spacing[1]);
  std::vector<Vec3> before(p.size());
  int frames = 0;
  while (frames < max_frames) {
    std::copy(p.position.begin(), p.position.end(), before.begin());
    solver.advance(frame);
    ++frames;
    float moved = 0.0f;
    for (std::size_t i = 0; i < p.size(); ++i) {
      moved = std::max(moved, (p.position[i] - before[i]).norm());
      p.velocity[i] = Vec3::Zero();
    }
    if (moved < still) break;
  }
  return frames;
}

}  // namespace sph
