// Vorticity confinement (Macklin & Mueller 2013 eq. 16, velocity_passes.h) on a Lamb-Oseen
// vortex sampled on a resting lattice: the push N x omega must turn with the vortex (it restores
// rotation that numerical damping took), be tangential, and scale with dt eps |omega|. The pbf
// preset leaves it off (params.cpp says why); a scene that sets `vorticity_confinement` gets this.
// Run on both pass forms by the unit tier (SPH_SIMD=scalar re-runs it on the scalar one).
#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <vector>

#include "sph/neighbor_grid.h"
#include "sph/params.h"
#include "sph/particles.h"
#include "sph/solvers/incompressible_setup.h"
#include "sph/solvers/velocity_passes.h"

namespace {

struct Vortex {
  double core = 0.0;         // r_c of the Lamb-Oseen profile
  double circulation = 0.0;  // Gamma
  Eigen::Vector3d axis_point;

  // omega_y(r) = Gamma / (pi r_c^2) exp(-r^2 / r_c^2); v_theta = Gamma / (2 pi r) (1 - exp(-r^2 / r_c^2)).
  double vorticity(double r) const {
    return circulation / (std::numbers::pi * core * core) * std::exp(-r * r / (core * core));
  }
  double speed(double r) const {
    if (r < 1e-9) return 0.0;
    return circulation / (2.0 * std::numbers::pi * r) * (1.0 - std::exp(-r * r / (core * core)));
  }
};

TEST(VorticityConfinement, PushTurnsWithTheVortexAndScalesWithEpsilon) {
  const sph::SimParams params = sph::pbfPreset();
  const auto classes = params.levelProps();
  const sph::LevelProps small = classes[sph::levelIndex(sph::Level{0})];
  const double s = std::cbrt(small.mass / params.rest_density);
  constexpr int kAcross = 20, kHigh = 8;
  Vortex vortex;
  vortex.core = 4.0 * s;
  vortex.circulation = 2.0 * std::numbers::pi * vortex.core * 0.5;  // about 0.3 m/s at the core's edge
  vortex.axis_point = Eigen::Vector3d(0.5 * kAcross * s, 0.0, 0.5 * kAcross * s);

  sph::ParticleSet p(kAcross * kAcross * kHigh);
  for (int iy = 0; iy < kHigh; ++iy) {
    for (int iz = 0; iz < kAcross; ++iz) {
      for (int ix = 0; ix < kAcross; ++ix) {
        const Eigen::Vector3d x((ix + 0.5) * s, (iy + 0.5) * s, (iz + 0.5) * s);
        const Eigen::Vector3d radial(x.x() - vortex.axis_point.x(), 0.0, x.z() - vortex.axis_point.z());
        const double r = radial.norm();
        // omega along +y: v = omega x r turns x into -z. The axis lies between lattice columns: r > 0.
        const Eigen::Vector3d tangent = Eigen::Vector3d::UnitY().cross(radial) / r;
        const std::uint32_t k = p.add(x.cast<float>(), (vortex.speed(r) * tangent).cast<float>(), sph::Level{0}, small);
        p.density[k] = static_cast<float>(params.rest_density);
      }
    }
  }
  sph::NeighborGrid grid;
  sph::Aabb bounds;
  bounds.min = Eigen::Vector3d::Zero();
  bounds.max = Eigen::Vector3d(kAcross * s, kHigh * s, kAcross * s);
  grid.configure(bounds, static_cast<float>(small.support), p.size());
  grid.build(p);

  sph::VelocityConstants c;
  c.kernels = sph::PairKernels::forClasses(classes);
  c.dt = 0.0025f;
  c.xsph = 0.0f;  // velocity_next = velocity before the confinement: the push alone remains
  std::vector<sph::Vec3> next(p.size()), vorticity(p.size());
  const sph::VelocityArrays a = sph::velocityArraysOf(p, next, vorticity, true, true, false);
  const sph::VelocityPassForms forms = sph::velocityPassForms();

  const auto pushes = [&](float epsilon) {
    c.vorticity_epsilon = epsilon;
    forms.smooth(a, c, grid);
    forms.confine(a, c, grid);
    std::vector<sph::Vec3> out(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) out[i] = next[i] - p.velocity[i];
    return out;
  };
  const std::vector<sph::Vec3> weak = pushes(0.5f);
  const std::vector<sph::Vec3> strong = pushes(1.0f);

  // Particles a support away from the lattice's faces (full neighbourhoods) and off the axis.
  const double support = small.support;
  int checked = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector3d x = p.position[i].cast<double>();
    const bool inside = x.minCoeff() > support && x.x() < kAcross * s - support && x.z() < kAcross * s - support &&
                        x.y() < kHigh * s - support;
    const Eigen::Vector3d radial(x.x() - vortex.axis_point.x(), 0.0, x.z() - vortex.axis_point.z());
    const double r = radial.norm();
    if (!inside || r < 1.5 * s || r > 2.0 * vortex.core) continue;
    ++checked;
    const Eigen::Vector3d tangent = Eigen::Vector3d::UnitY().cross(radial) / r;
    const Eigen::Vector3d push = weak[i].cast<double>();
    const double along = push.dot(tangent);
    const double expected = c.dt * 0.5 * vortex.vorticity(r);  // dt eps |omega|, N x omega a unit turn
    EXPECT_GT(along, 0.5 * expected) << "particle " << i << " at r = " << r / s << " spacings";
    EXPECT_LT(along, 1.5 * expected) << "particle " << i << " at r = " << r / s << " spacings";
    EXPECT_LT(std::abs(push.dot(radial / r)), 0.2 * along) << "particle " << i << ": not tangential";
    // Twice epsilon, twice the push.
    EXPECT_NEAR(strong[i].cast<double>().dot(tangent), 2.0 * along, 1e-3 * along + 1e-9);
  }
  EXPECT_GE(checked, 20);
}

}  // namespace
