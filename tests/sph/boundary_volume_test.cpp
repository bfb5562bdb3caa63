// The walls' volume (boundary_volume.h): a resting lattice of the incompressible presets sits at
// rest density at faces, edges and corners, with the density gradient of the interior (none), so
// resting water at a wall feels no push; obstacles add volume where they are.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sph/boundary_volume.h"
#include "sph/params.h"
#include "sph/solvers/incompressible_setup.h"

namespace {

struct LatticeProbe {
  double density;            // over rho0
  Eigen::Vector3d gradient;  // (sum_j m_j grad W_ij + rho0 grad Phi) / rho0, in 1 / m
};

// Particle at lattice point (i, j, k) of a lattice filling the box corner region x, y, z >= 0 at
// spacing s (points at (n + 1/2) s), class c of the preset.
LatticeProbe probe(const sph::Scene& scene, const sph::IncompressibleSetup& setup, int c, int i, int j, int k) {
  const auto cu = static_cast<std::size_t>(c);
  const double s = setup.spacing[cu];
  const sph::CubicKernel& kernel = setup.kernels[cu];
  const Eigen::Vector3d x((i + 0.5) * s, (j + 0.5) * s, (k + 0.5) * s);
  const int reach = static_cast<int>(std::ceil(kernel.h / s)) + 1;
  LatticeProbe out{0.0, Eigen::Vector3d::Zero()};
  const double volume = s * s * s;
  for (int a = i - reach; a <= i + reach; ++a) {
    for (int b = j - reach; b <= j + reach; ++b) {
      for (int d = k - reach; d <= k + reach; ++d) {
        if (a < 0 || b < 0 || d < 0) continue;
        const Eigen::Vector3d y((a + 0.5) * s, (b + 0.5) * s, (d + 0.5) * s);
        const Eigen::Vector3d r = x - y;
        const auto rl = static_cast<float>(r.norm());
        out.density += volume * sph::cubicW(kernel, rl);
        out.gradient += volume * sph::cubicGradFactor(kernel, rl) * r;
      }
    }
  }
  const sph::BoundarySample wall = setup.boundary->sample(x.cast<float>(), c, scene.boundary.stateAt(0.0));
  out.density += wall.phi;
  out.gradient += wall.grad.cast<double>();
  return out;
}

sph::Scene boxScene(const std::string& preset) {
  sph::Scene scene;
  EXPECT_TRUE(sph::presetByName(preset, scene.params));
  scene.boundary.box.max = Eigen::Vector3d(1.0, 1.0, 1.0);
  return scene;
}

TEST(BoundaryVolume, RestingLatticeSitsAtRestDensityAtFacesEdgesAndCorners) {
  const sph::Scene scene = boxScene("pbf");
  const sph::IncompressibleSetup setup = sph::makeIncompressibleSetup(scene);
  for (int c = 0; c < scene.params.levels; ++c) {
    // Gradient scale: |grad rho| / rho0 of a particle that lost half its neighbours.
    const double scale = 1.0 / setup.kernels[static_cast<std::size_t>(c)].h;
    for (const auto& [i, j, k] : std::vector<std::array<int, 3>>{{10, 10, 10},
                                                                 {10, 0, 10},
                                                                 {10, 1, 11},
                                                                 {0, 0, 10},
                                                                 {1, 0, 11},
                                                                 {0, 0, 0},
                                                                 {1, 1, 0},
                                                                 {2, 0, 0},
                                                                 {1, 0, 1},
                                                                 {1, 1, 2},
                                                                 {0, 1, 1},
                                                                 {0, 2, 0}}) {
      SCOPED_TRACE(::testing::Message() << "class " << c << " lattice point " << i << "," << j << "," << k);
      const LatticeProbe p = probe(scene, setup, c, i, j, k);
      EXPECT_NEAR(p.density, 1.0, 1e-3);
      // The pressure force carries k_i (sum_j m_j grad W_ij + rho0 grad Phi): any residual here is
      // multiplied by the absolute pressure, which at depth is many times the weight's share of a
      // particle. A continuous wall integral leaves 2e-2 of the scale; the lattice's own sums, float noise.
      EXPECT_LT(p.gradient.norm(), 1e-3 * scale) << p.gradient.transpose();
    }
  }
}

}  // namespace

namespace {

// grad Phi is the derivative of Phi (finite differences), anywhere near faces, edges and corners.
TEST(BoundaryVolume, GradientIsTheDerivativeOfTheVolume) {
  const sph::Scene scene = boxScene("pbf");
  const sph::IncompressibleSetup setup = sph::makeIncompressibleSetup(scene);
  const sph::BoxState box = scene.boundary.stateAt(0.0);
  for (int c = 0; c < scene.params.levels; ++c) {
    const float s = setup.spacing[static_cast<std::size_t>(c)];
    for (const sph::Vec3& x : {sph::Vec3(0.5f, 0.3f * s, 0.5f), sph::Vec3(0.3f * s, 0.3f * s, 0.5f),
                               sph::Vec3(0.35f * s, 0.4f * s, 0.3f * s), sph::Vec3(0.8f * s, 1.3f * s, 0.5f),
                               sph::Vec3(1.1f * s, 0.6f * s, 0.9f * s)}) {
      SCOPED_TRACE(::testing::Message() << "class " << c << " at " << x.transpose() / s << " spacings");
      const sph::BoundarySample at = setup.boundary->sample(x, c, box);
      const float e = 1e-3f * s;
      for (int a = 0; a < 3; ++a) {
        sph::Vec3 step = sph::Vec3::Zero();
        step[a] = e;
        const float numeric =
            (setup.boundary->sample(x + step, c, box).phi - setup.boundary->sample(x - step, c, box).phi) / (2 * e);
        EXPECT_NEAR(at.grad[a], numeric, 0.02f * (std::abs(numeric) + 1.0f / s)) << "axis " << a;
        EXPECT_LE(at.grad[a], 1e-3f / s) << "the volume grows towards the walls, axis " << a;
      }
    }
  }
}

}  // namespace
