// A closed tank of water at rest (scenes/validation/hydrostatic.json in small, built here): the
// incompressible presets must hold it at rest density, with walls and floor at rest density too,
// the hydrostatic pressure, and no motion once settled. And they give the same particles, bit for
// bit, on one thread and on two.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "sph/simulation.h"

namespace {

// A tank nx x nx lattice spacings wide, water ny layers deep filling its floor wall to wall (so
// the resting lattice is the one the walls' volume continues, boundary_volume.h).
sph::Scene tank(const std::string& preset, int nx, int ny) {
  sph::Scene scene;
  scene.name = "hydrostatic";
  scene.source = "hydrostatic_test";
  EXPECT_TRUE(sph::presetByName(preset, scene.params));
  const double s = std::cbrt(scene.params.mass_small / scene.params.rest_density);
  const double width = nx * s;
  scene.boundary.box.min = Eigen::Vector3d::Zero();
  scene.boundary.box.max = Eigen::Vector3d(width, (ny + 4) * s, width);
  scene.water.min = Eigen::Vector3d::Zero();
  scene.water.max = Eigen::Vector3d(width, ny * s + 1e-6, width);
  scene.large_particles = nx * nx * ny / 2;  // the regular method's L0 particles: nx^2 ny
  return scene;
}

struct Rest {
  double mean_density_error = 0.0;        // mean |rho / rho0 - 1| below the surface layers
  double wall_min = 1.0, wall_max = 1.0;  // rho / rho0 of the particles at walls and floor
  double rms_speed = 0.0;
  double slope_ratio = 0.0;  // -dp/dy / (rho0 g) in the interior, the mean over the measured second
};

// The highest particle's centre: the surface the measurements keep their distance from.
float highest(const sph::ParticleSet& p) {
  float top = -1e9f;
  for (std::size_t i = 0; i < p.size(); ++i) top = std::max(top, p.position[i].y());
  return top;
}

// How far x is from the nearest side wall.
double sideDistance(const sph::BoxState& box, const sph::Vec3& x) {
  return std::min({x.x() - box.min.x(), box.max.x() - x.x(), x.z() - box.min.z(), box.max.z() - x.z()});
}

Rest measure(const sph::Simulation& sim) {
  const sph::ParticleSet& p = sim.particles();
  const sph::SimParams& params = sim.params();
  const double rho0 = params.rest_density;
  const double s = std::cbrt(params.mass_small / rho0);
  const sph::BoxState box = sim.boxNow();
  const float top = highest(p);
  Rest out;
  out.wall_min = 1e9;
  out.wall_max = -1e9;
  double v2 = 0.0, error = 0.0;
  int below = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const sph::Vec3& x = p.position[i];
    v2 += p.velocity[i].squaredNorm();
    const double side = sideDistance(box, x);
    const double floor = x.y() - box.min.y();
    const double depth = top - x.y();
    const double rho = p.density[i] / rho0;
    if (depth < 1.5 * s) continue;  // the free surface's layer is under-dense by nature
    error += std::abs(rho - 1.0);
    ++below;
    if (std::min(side, floor) < 0.75 * s) {
      out.wall_min = std::min(out.wall_min, rho);
      out.wall_max = std::max(out.wall_max, rho);
    }
  }
  out.rms_speed = std::sqrt(v2 / static_cast<double>(p.size()));
  out.mean_density_error = error / std::max(below, 1);
  return out;
}

// -dp/dy / (rho0 g) in the interior: the least-squares slope p = a + b y over the particles
// farther than a support from walls, floor and surface, each with its own pressure.
double pressureSlope(const sph::Simulation& sim) {
  const sph::ParticleSet& p = sim.particles();
  const double rho0 = sim.params().rest_density;
  const double s = std::cbrt(sim.params().mass_small / rho0);
  const sph::BoxState box = sim.boxNow();
  const float top = highest(p);
  double sy = 0.0, sp = 0.0, syy = 0.0, syp = 0.0;
  int interior = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const sph::Vec3& x = p.position[i];
    const double side = sideDistance(box, x);
    if (side <= 2.5 * s || x.y() - box.min.y() <= 2.5 * s || top - x.y() <= 2.5 * s) continue;
    ++interior;
    sy += x.y();
    sp += p.pressure[i];
    syy += static_cast<double>(x.y()) * x.y();
    syp += static_cast<double>(x.y()) * p.pressure[i];
  }
  EXPECT_GT(interior, 20);
  const double slope = (syp - sy * sp / interior) / (syy - sy * sy / interior);
  return -slope / (rho0 * std::abs(sim.params().gravity));
}

double rmsSpeed(const sph::ParticleSet& p) {
  double v2 = 0.0;
  for (const sph::Vec3& v : p.velocity) v2 += v.squaredNorm();
  return std::sqrt(v2 / static_cast<double>(std::max<std::size_t>(p.size(), 1)));
}

// nx x nx spacings, 14 layers deep (10 wide: 1,400 particles, 0.3 m of water), settled: at least 2 s, then
// until the rms speed is below 3 mm/s, for at most 8 s of simulated time (the scalar and the
// AVX-512 forms round differently and settle up to a second apart), and measured 1 s after that,
// where it must still be below the 5 mm/s asked. (dfsph's conjugate gradients pass 5 mm/s at
// about 2.3 s and read 4.6 mm/s a second later; 2.3 from 4.5 s on.)
// One thread: the result is the same on any count (below), and a small set on two threads of a
// busy machine spends its time waiting at the barriers.
void expectRest(const std::string& preset, int nx) {
  const int previous = omp_get_max_threads();
  omp_set_num_threads(1);
  sph::Simulation sim(tank(preset, nx, 14), sph::Level{0});
  ASSERT_EQ(sim.particles().size(), static_cast<std::size_t>(nx * nx * 14));
  for (int f = 0; f < 800 && (f < 200 || rmsSpeed(sim.particles()) >= 3e-3); ++f) sim.step();
  std::printf("%s: settled at t = %.2f s\n", preset.c_str(), sim.time());
  // Then it must stay at rest: the measurement is a second later, the pressure's slope its mean
  // over that second (every fifth frame). A particle's pressure is one step's multiplier: at rest
  // the slope of a single frame scattered 0.90-1.01 from frame to frame in dfsph's tank (0.94-1.01
  // with the interior's bounds moved by half a spacing). The SPH-interpolated pressure at gauges
  // read pbf's slope 1.02-1.07 where its particles read 1.00-1.03 (docs/fluids.md).
  double slopes = 0.0;
  for (int f = 1; f <= 100; ++f) {
    sim.step();
    if (f % 5 == 0) slopes += pressureSlope(sim);
  }
  omp_set_num_threads(previous);
  Rest r = measure(sim);
  r.slope_ratio = slopes / 20.0;
  std::printf("%s: mean |rho/rho0 - 1| %.5f, walls and floor [%.4f, %.4f] rho0, rms %.5f m/s, slope %.4f rho0 g\n",
              preset.c_str(), r.mean_density_error, r.wall_min, r.wall_max, r.rms_speed, r.slope_ratio);
  SCOPED_TRACE(::testing::Message() << preset << ": mean |rho/rho0 - 1| " << r.mean_density_error << ", walls ["
                                    << r.wall_min << ", " << r.wall_max << "], rms " << r.rms_speed << " m/s, slope "
                                    << r.slope_ratio << " rho0 g");
  EXPECT_LE(r.mean_density_error, 0.01);
  EXPECT_GE(r.wall_min, 0.98);
  EXPECT_LE(r.wall_max, 1.02);
  EXPECT_LT(r.rms_speed, 5e-3);
  EXPECT_NEAR(r.slope_ratio, 1.0, 0.05);
}

TEST(Hydrostatic, PbfHoldsTheTankAtRest) { expectRest("pbf", 10); }

TEST(Hydrostatic, DfsphHoldsTheTankAtRest) { expectRest("dfsph", 10); }

// The wall layers' densest particles depend on the tank's width: the layer above the floor pressed
// sideways onto the guard beside a vertical edge. 12 spacings wide pbf holds them within 2 % as at
// 10 (1.015 rho0); dfsph did so only at 10 (1.027 at 12) until its side walls' guard moved from
// 0.4 to 0.3 spacings (incompressible_setup.cpp; 1.007, and 1.002 since its solve holds the floor
// layer itself, floor_contact.h).
TEST(Hydrostatic, PbfHoldsAWiderTankAtRest) { expectRest("pbf", 12); }

TEST(Hydrostatic, DfsphHoldsAWiderTankAtRest) { expectRest("dfsph", 12); }

double meanCompression(const sph::Simulation& sim) {
  const sph::ParticleSet& p = sim.particles();
  double sum = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    sum += std::max(static_cast<double>(p.density[i]) / sim.params().rest_density - 1.0, 0.0);
  }
  return sum / static_cast<double>(p.size());
}

// A column 40 layers deep (4 x 4 spacings, 640 particles): pbf's 3 iterations a step carry the
// pressure only so far down, and it settles 1.5 % compressed; with a tolerance a step iterates
// on until the mean compression is within it (the preset's 1 %; here 0.5 %, to stand clear of
// the fixed count's). The check comes before each correction, so the last iteration is one more
// than needed. Measured after the settle and 50 frames at rest. (The centre of mass sits lower
// than the lattice's in both, mostly from the settle at the walls and the surface.)
TEST(Hydrostatic, PbfIteratesDeepWaterToItsTolerance) {
  const int previous = omp_get_max_threads();
  omp_set_num_threads(1);
  double compression[2] = {0.0, 0.0};
  int iterations[2] = {0, 0};
  double sunk[2] = {0.0, 0.0};  // the centre of mass's drop below the incompressible column's, relative
  for (int fixed = 0; fixed < 2; ++fixed) {
    sph::Scene scene = tank("pbf", 4, 40);
    EXPECT_GT(scene.params.pbf_density_tolerance, 0.0);  // the preset iterates to one
    scene.params.pbf_density_tolerance = fixed == 1 ? 0.0 : 0.005;
    sph::Simulation sim(scene, sph::Level{0});
    ASSERT_EQ(sim.particles().size(), 640u);
    for (int f = 0; f < 50; ++f) sim.step();
    compression[fixed] = meanCompression(sim);
    iterations[fixed] = sim.lastSolverStats().iterations;
    double y = 0.0;
    for (const sph::Vec3& x : sim.particles().position) y += x.y();
    const double s = std::cbrt(scene.params.mass_small / scene.params.rest_density);
    sunk[fixed] = 1.0 - y / static_cast<double>(sim.particles().size()) / (20.0 * s);
  }
  omp_set_num_threads(previous);
  std::printf(
      "deep column: mean compression %.4f with the tolerance (%d iterations a frame), %.4f with 3 a step (%d); centre "
      "of mass lower by %.4f, %.4f\n",
      compression[0], iterations[0], compression[1], iterations[1], sunk[0], sunk[1]);
  EXPECT_LE(compression[0], 0.005);  // as the last check measured it (at most 20 iterations a step)
  EXPECT_GT(compression[1], 0.01);
  EXPECT_GT(iterations[0], iterations[1]);
  // And the water stands higher: its centre of mass, a measure the solver does not steer by.
  EXPECT_LT(sunk[0], sunk[1] - 0.005);
}

// dfsph's constant-density solve turns to conjugate gradients after three Jacobi iterations
// (dfsph_conjugate_gradients.cpp; the preset's, "conjugate_gradients": false keeps Jacobi): in a
// tank 24 layers deep (8 x 8 spacings, 1,536 particles) it must reach the same tolerance in fewer
// iterations than Jacobi throughout (a third of them, 34 a frame against 97-100), leave the water
// as near rho0 and moving no faster (still settling at 1.5 s, 0.011-0.015 m/s both ways), and
// give the same particles on 1 and 2 threads (its step lengths are sums in a fixed order).
// Measured over frames 100-150.
TEST(Hydrostatic, DfsphConjugateGradientsReachTheToleranceInFewerIterations) {
  const int previous = omp_get_max_threads();
  long iterations[3] = {0, 0, 0};
  double compression[3] = {0.0, 0.0, 0.0};
  double rms[3] = {0.0, 0.0, 0.0};
  std::vector<sph::Vec3> position[3];
  // 0: conjugate gradients, 1: Jacobi, 2: conjugate gradients on two threads.
  for (int run = 0; run < 3; ++run) {
    omp_set_num_threads(run == 2 ? 2 : 1);
    sph::Scene scene = tank("dfsph", 8, 24);
    EXPECT_TRUE(scene.params.dfsph_conjugate_gradients);  // the preset's
    scene.params.dfsph_conjugate_gradients = run != 1;
    sph::Simulation sim(scene, sph::Level{0});
    ASSERT_EQ(sim.particles().size(), 1536u);
    for (int f = 0; f < 100; ++f) sim.step();
    for (int f = 0; f < 50; ++f) {
      sim.step();
      iterations[run] += sim.lastSolverStats().iterations;
    }
    compression[run] = meanCompression(sim);
    rms[run] = rmsSpeed(sim.particles());
    position[run] = sim.particles().position;
  }
  omp_set_num_threads(previous);
  std::printf(
      "24 layers, frames 100-150: conjugate gradients %ld iterations, mean compression %.5f, rms %.4f m/s; "
      "Jacobi %ld, %.5f, %.4f m/s\n",
      iterations[0], compression[0], rms[0], iterations[1], compression[1], rms[1]);
  EXPECT_LT(iterations[0], iterations[1] / 2);
  EXPECT_LT(compression[0], compression[1] + 0.001);
  EXPECT_LT(rms[0], 1.5 * rms[1]);
  EXPECT_EQ(iterations[2], iterations[0]);
  EXPECT_TRUE(position[2] == position[0]);
}

struct State {
  std::vector<std::uint32_t> id;
  std::vector<sph::Vec3> position, velocity;
};

State runWithThreads(const std::string& preset, int threads, int steps) {
  const int previous = omp_get_max_threads();
  omp_set_num_threads(threads);
  sph::Simulation sim(tank(preset, 6, 8), sph::Level{0});
  // Stir the settled water (a shear and a swirl), so that the steps move it.
  sph::ParticleSet& p = sim.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const sph::Vec3& x = p.position[i];
    p.velocity[i] =
        sph::Vec3(0.3f * std::sin(40.0f * x.y()), 0.1f * std::cos(30.0f * x.x()), 0.2f * std::sin(50.0f * x.x()));
  }
  for (int s = 0; s < steps; ++s) sim.step();
  omp_set_num_threads(previous);
  return {sim.particles().id, sim.particles().position, sim.particles().velocity};
}

void expectThreadIndependent(const std::string& preset) {
  const State one = runWithThreads(preset, 1, 30);
  const State two = runWithThreads(preset, 2, 30);
  ASSERT_EQ(one.id, two.id);
  std::size_t differing = 0;
  for (std::size_t i = 0; i < one.position.size(); ++i) {
    if (std::memcmp(one.position[i].data(), two.position[i].data(), sizeof(float) * 3) != 0 ||
        std::memcmp(one.velocity[i].data(), two.velocity[i].data(), sizeof(float) * 3) != 0) {
      ++differing;
    }
  }
  EXPECT_EQ(differing, 0u) << preset;
  // The water moved (the run tested something).
  double moved = 0.0;
  for (const sph::Vec3& v : one.velocity) moved = std::max(moved, static_cast<double>(v.norm()));
  EXPECT_GT(moved, 0.05) << preset;
}

TEST(Hydrostatic, PbfIndependentOfThreadCount) { expectThreadIndependent("pbf"); }
TEST(Hydrostatic, DfsphIndependentOfThreadCount) { expectThreadIndependent("dfsph"); }

}  // namespace
