// sph_validate's measurements (bench/validation.h) on inputs whose answers are known: the
// experiment's own curve has no error, a late curve is found late and a shift within the limit
// repairs it, a lattice column reads its own height at the wall whatever its particles' level, and
// a lattice with hydrostatic pressure gives rho0 g as its pressure slope.
#include <gtest/gtest.h>

#include <cmath>

#include "bench/validation.h"
#include "sph/params.h"

namespace {

TEST(Validation, TheExperimentMatchesItself) {
  const auto& mm = bench::martinMoyceN2();
  ASSERT_EQ(mm.size(), 16u);
  EXPECT_DOUBLE_EQ(bench::maxRelativeError(mm, mm, 3.0, 0.0), 0.0);
}

TEST(Validation, ALateFrontIsLateAndAShiftRepairsIt) {
  std::vector<bench::CurvePoint> late;
  for (const auto& p : bench::martinMoyceN2()) late.push_back({p.T + 0.15, p.value});
  late.insert(late.begin(), {0.0, 1.0});
  EXPECT_GT(bench::maxRelativeError(late, bench::martinMoyceN2(), 3.0, 0.0), 0.05);
  double error = 1.0;
  // The shift delays the experiment, not the simulation: a late simulation cannot be shifted back.
  bench::bestStartupShift(late, bench::martinMoyceN2(), 3.0, 0.2, error);
  EXPECT_GT(error, 0.05);
  std::vector<bench::CurvePoint> early;
  for (const auto& p : bench::martinMoyceN2()) early.push_back({std::max(0.0, p.T - 0.15), p.value});
  const double shift = bench::bestStartupShift(early, bench::martinMoyceN2(), 3.0, 0.2, error);
  EXPECT_NEAR(shift, 0.15, 0.0011);
  EXPECT_LT(error, 0.01);
  // A curve that stops before T = 3 cannot pass.
  std::vector<bench::CurvePoint> short_run(bench::martinMoyceN2().begin(), bench::martinMoyceN2().begin() + 5);
  EXPECT_TRUE(std::isinf(bench::maxRelativeError(short_run, bench::martinMoyceN2(), 3.0, 0.0)));
}

TEST(Validation, TheResidualHeightIsMartinAndMoycesTableInT) {
  const auto& mm = bench::martinMoyceHeightN2();
  ASSERT_EQ(mm.size(), 18u);
  EXPECT_DOUBLE_EQ(bench::maxRelativeError(mm, mm, 3.0, 0.0), 0.0);
  EXPECT_EQ(mm.front().T, 0.0);
  EXPECT_EQ(mm.front().value, 1.0);
  for (std::size_t k = 1; k < mm.size(); ++k) {
    EXPECT_GT(mm[k].T, mm[k - 1].T);
    EXPECT_LT(mm[k].value, mm[k - 1].value);
  }
  // The table's tau = t sqrt(g / a) is T / sqrt(2): half the column is left at tau = 2.00.
  EXPECT_NEAR(bench::curveAt(mm, 2.00 * std::sqrt(2.0)), 0.50, 1e-12);
  // No faster than free fall: the top falls at most g t^2 / 2 = a T^2 / 4, a T^2 / 8 of 2 a.
  for (const auto& p : mm) EXPECT_GE(p.value, 1.0 - p.T * p.T / 8.0 - 1e-9) << "T " << p.T;
}

// A column of `level` particles on a lattice at rest density against the wall x = 0: 10 spacings
// of the finest level long, 8 deep (the tank's depth) and 30 high.
double latticeColumnHeight(sph::Level level, double& column_height) {
  sph::Scene scene;
  EXPECT_TRUE(sph::presetByName("pbf", scene.params));
  const double rho0 = scene.params.rest_density;
  const double fine = std::cbrt(scene.params.mass_small / rho0);
  const sph::LevelProps props = scene.params.levelProps()[sph::levelIndex(level)];
  const double s = std::cbrt(props.mass / rho0);
  scene.boundary.box.max = Eigen::Vector3d(1.0, 1.0, 8 * fine);
  const int nx = static_cast<int>(std::lround(10 * fine / s));
  const int nz = static_cast<int>(std::lround(8 * fine / s));
  const int ny = static_cast<int>(std::lround(30 * fine / s));
  sph::ParticleSet p(static_cast<std::size_t>(nx * ny * nz));
  for (int y = 0; y < ny; ++y) {
    for (int z = 0; z < nz; ++z) {
      for (int x = 0; x < nx; ++x) {
        p.add(sph::Vec3(static_cast<float>((x + 0.5) * s), static_cast<float>((y + 0.5) * s),
                        static_cast<float>((z + 0.5) * 8 * fine / nz)),
              sph::Vec3::Zero(), level, props);
      }
    }
  }
  column_height = ny * s;
  return bench::residualHeight(p, scene, scene.boundary.stateAt(0.0));
}

TEST(Validation, TheResidualHeightIsALatticeColumnsTopAtEveryLevel) {
  for (const sph::Level level : {sph::Level{0}, sph::Level{1}, sph::Level{3}}) {
    double height = 0.0;
    const double read = latticeColumnHeight(level, height);
    EXPECT_NEAR(read, height, 0.01 * height) << "level " << sph::levelIndex(level);
  }
}

TEST(Validation, FrontIgnoresAFewSprayParticles) {
  sph::ParticleSet p(4000);
  sph::LevelProps props;
  props.mass = 998.29e-6;  // a 10 mm lattice
  for (int i = 0; i < 3000; ++i)
    p.add(sph::Vec3(0.01f * (i % 30) + 0.005f, 0.0f, 0.0f), sph::Vec3::Zero(), sph::Level{0}, props);
  p.add(sph::Vec3(2.0f, 0.0f, 0.0f), sph::Vec3::Zero(), sph::Level{0}, props);  // a drop far ahead
  EXPECT_NEAR(bench::surgeFrontX(p, 998.29), 0.30, 1e-4);
  const bench::Column c = bench::measureColumn(p, 998.29, 0.0);
  EXPECT_NEAR(c.width, 2.005, 1e-4) << "the column is measured at the start, before any spray";
}

TEST(Validation, ColumnReportsTheCompressionItIsReleasedWith) {
  const double rho0 = 998.29;
  sph::ParticleSet p(4);
  sph::LevelProps props;
  props.mass = rho0 * 1e-6;                               // a 10 mm lattice
  const float densities[4] = {0.9f, 1.0f, 1.02f, 1.10f};  // an under-dense surface particle counts as 0
  for (float d : densities) {
    const std::uint32_t i = p.add(sph::Vec3(0.005f, 0.005f, 0.005f), sph::Vec3::Zero(), sph::Level{0}, props);
    p.density[i] = static_cast<float>(d * rho0);
  }
  const bench::Column c = bench::measureColumn(p, rho0, 0.0);
  EXPECT_NEAR(c.mean_compression, (0.02 + 0.10) / 4.0, 1e-6);
  EXPECT_NEAR(c.max_density, 1.10, 1e-6);
  // Before any density is computed (the thesis's solver, at release) there is nothing to report.
  for (std::size_t i = 0; i < p.size(); ++i) p.density[i] = 0.0f;
  const bench::Column unknown = bench::measureColumn(p, rho0, 0.0);
  EXPECT_TRUE(std::isnan(unknown.mean_compression));
  EXPECT_TRUE(std::isnan(unknown.max_density));
}

TEST(Validation, HydrostaticLatticeHasSlopeRho0G) {
  const double rho0 = 998.29, s = 0.01;
  sph::ParticleSet p(20000);
  sph::LevelProps props;
  props.mass = rho0 * s * s * s;
  const int n = 10, layers = 30;
  for (int y = 0; y < layers; ++y) {
    for (int z = 0; z < n; ++z) {
      for (int x = 0; x < n; ++x) {
        const std::size_t i = p.size();
        p.add(sph::Vec3((x + 0.5f) * s, (y + 0.5f) * s, (z + 0.5f) * s), sph::Vec3::Zero(), sph::Level{0}, props);
        p.density[i] = static_cast<float>(rho0 * (x == 0 ? 1.03 : 1.0));  // one wall layer 3 % dense
        p.pressure[i] = static_cast<float>(rho0 * 9.81 * (layers - y - 0.5) * s);
      }
    }
  }
  const bench::RestProfile r =
      bench::measureRestProfile(p, rho0, Eigen::Vector3f::Zero(), Eigen::Vector3f(n * s, 1.0f, n * s), 2.0 * s);
  EXPECT_NEAR(r.surface_y, layers * s, 1e-6);
  EXPECT_NEAR(r.pressure_slope / (rho0 * 9.81), 1.0, 1e-3);
  EXPECT_NEAR(r.mean_density_error, 0.003, 1e-4);  // a tenth of the particles 3 % off
  EXPECT_GT(r.wall_density_error, 0.005) << "the dense wall layer is seen";
  // and each of its particles: the range over the wall and floor layers below the top two
  EXPECT_NEAR(r.wall_max, 1.03, 1e-6);
  EXPECT_NEAR(r.wall_min, 1.0, 1e-6);
  EXPECT_DOUBLE_EQ(r.rms_speed, 0.0);
}

}  // namespace
