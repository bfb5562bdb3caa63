// Collision response, eqs. (3.23)-(3.32): a penetrating particle goes to the contact point, its
// radius included, and loses the part of its velocity (relative to the surface) that points in.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "sph/collision.h"
#include "sph/params.h"
#include "sph/solvers/thesis/thesis_stages.h"

namespace {

using sph::Vec3;

constexpr float kR = 0.01f;  // particle radius
constexpr float kTol = 1e-5f;

TEST(CollideSphere, PushesToSurfaceAndRemovesInwardVelocity) {
  sph::Sphere s{Eigen::Vector3d(0.5, 0.4, 0.3), 0.1};
  const Vec3 c = s.centre.cast<float>();
  const Vec3 n = Vec3(1.0f, 2.0f, -0.5f).normalized();
  const Vec3 t = n.cross(Vec3::UnitX()).normalized();  // tangential
  Vec3 x = c + 0.05f * n;
  Vec3 u = -2.0f * n + 0.3f * t;
  ASSERT_TRUE(sph::collideSphere(s, kR, x, u));
  EXPECT_NEAR((x - c).norm(), 0.1f + kR, kTol);
  EXPECT_NEAR((x - c).normalized().dot(n), 1.0f, kTol);
  EXPECT_NEAR(u.dot(n), 0.0f, kTol);
  EXPECT_NEAR(u.dot(t), 0.3f, kTol);
}

TEST(CollideSphere, KeepsOutwardVelocity) {
  sph::Sphere s{Eigen::Vector3d(0.0, 0.0, 0.0), 0.2};
  Vec3 x(0.0f, 0.15f, 0.0f);
  Vec3 u(0.1f, 1.5f, 0.0f);
  const Vec3 u0 = u;
  ASSERT_TRUE(sph::collideSphere(s, kR, x, u));
  EXPECT_NEAR(x.y(), 0.2f + kR, kTol);
  EXPECT_EQ(u, u0);
}

TEST(CollideSphere, NoContactLeavesParticleUnchanged) {
  sph::Sphere s{Eigen::Vector3d(0.0, 0.0, 0.0), 0.2};
  Vec3 x(0.0f, 0.0f, 0.2f + 1.5f * kR);
  Vec3 u(0.0f, 0.0f, -3.0f);
  const Vec3 x0 = x, u0 = u;
  EXPECT_FALSE(sph::collideSphere(s, kR, x, u));
  EXPECT_EQ(x, x0);
  EXPECT_EQ(u, u0);
}

TEST(CollideCylinder, PushesOutInXzAndLeavesYAlone) {
  sph::Cylinder cyl{0.3, 0.4, 0.05};
  const Vec3 n = Vec3(0.6f, 0.0f, -0.8f);
  Vec3 x(0.3f + 0.02f * n.x(), 0.77f, 0.4f + 0.02f * n.z());
  Vec3 u = -1.0f * n + Vec3(0.0f, -0.9f, 0.0f) + 0.2f * Vec3(0.8f, 0.0f, 0.6f);
  ASSERT_TRUE(sph::collideCylinder(cyl, kR, x, u));
  EXPECT_NEAR(std::hypot(x.x() - 0.3f, x.z() - 0.4f), 0.05f + kR, kTol);
  EXPECT_NEAR((x.x() - 0.3f) * n.x() + (x.z() - 0.4f) * n.z(), 0.05f + kR, kTol);
  EXPECT_EQ(x.y(), 0.77f);
  EXPECT_NEAR(u.dot(n), 0.0f, kTol);
  EXPECT_NEAR(u.dot(Vec3(0.8f, 0.0f, 0.6f)), 0.2f, kTol);
  EXPECT_EQ(u.y(), -0.9f);
}

TEST(CollideCylinder, KeepsOutwardVelocityAndIgnoresFarParticles) {
  sph::Cylinder cyl{0.0, 0.0, 0.1};
  Vec3 x(0.05f, 0.2f, 0.0f);
  Vec3 u(0.5f, 0.0f, 0.1f);
  const Vec3 u0 = u;
  ASSERT_TRUE(sph::collideCylinder(cyl, kR, x, u));
  EXPECT_NEAR(x.x(), 0.1f + kR, kTol);
  EXPECT_EQ(u, u0);

  Vec3 far(0.0f, 5.0f, -0.2f);
  Vec3 uf(0.0f, 0.0f, 1.0f);
  const Vec3 far0 = far, uf0 = uf;
  EXPECT_FALSE(sph::collideCylinder(cyl, kR, far, uf));
  EXPECT_EQ(far, far0);
  EXPECT_EQ(uf, uf0);
}

sph::BoxState unitBox() {
  sph::BoxState b;
  b.min = Vec3(0.0f, 0.0f, 0.0f);
  b.max = Vec3(1.0f, 0.5f, 0.8f);
  return b;
}

TEST(CollideBox, ClampsInsideAndRemovesVelocityIntoWalls) {
  const sph::BoxState b = unitBox();
  Vec3 x(-0.05f, 0.6f, 0.4f);
  Vec3 u(-1.0f, 2.0f, 0.3f);
  ASSERT_TRUE(sph::collideBox(b, kR, x, u));
  EXPECT_EQ(x.x(), 0.0f + kR);
  EXPECT_EQ(x.y(), 0.5f - kR);
  EXPECT_EQ(x.z(), 0.4f);
  EXPECT_EQ(u.x(), 0.0f);
  EXPECT_EQ(u.y(), 0.0f);
  EXPECT_EQ(u.z(), 0.3f);
}

TEST(CollideBox, KeepsVelocityAwayFromWall) {
  const sph::BoxState b = unitBox();
  Vec3 x(0.5f, 0.25f, 0.805f);
  Vec3 u(0.1f, 0.2f, -0.7f);
  const Vec3 u0 = u;
  ASSERT_TRUE(sph::collideBox(b, kR, x, u));
  EXPECT_EQ(x.z(), 0.8f - kR);
  EXPECT_EQ(u, u0);
}

TEST(CollideBox, MovingWallDragsParticleAlong) {
  sph::BoxState b = unitBox();
  b.min_velocity.x() = 0.5f;
  Vec3 x(0.0f, 0.25f, 0.4f);
  Vec3 u(0.1f, 0.0f, 0.0f);
  ASSERT_TRUE(sph::collideBox(b, kR, x, u));
  EXPECT_EQ(x.x(), kR);
  EXPECT_EQ(u.x(), 0.5f);  // at least the wall velocity

  Vec3 x2(0.0f, 0.25f, 0.4f);
  Vec3 u2(0.9f, 0.0f, 0.0f);  // already faster than the wall
  ASSERT_TRUE(sph::collideBox(b, kR, x2, u2));
  EXPECT_EQ(u2.x(), 0.9f);
}

// dfsph keeps its particles further off the floor than off the other faces (incompressible_setup.cpp).
TEST(CollideBox, FloorReachAppliesToTheLowestFaceAlone) {
  const sph::BoxState b = unitBox();
  const sph::WallReach reach(0.04f, 0.03f);
  Vec3 x(-0.1f, -0.1f, 0.9f);
  Vec3 u(-1.0f, -1.0f, 1.0f);
  ASSERT_TRUE(sph::collideBox(b, reach, x, u));
  EXPECT_EQ(x, Vec3(0.03f, 0.04f, 0.8f - 0.03f));
  EXPECT_EQ(u, Vec3::Zero());
  Vec3 top(0.5f, 0.6f, 0.4f);
  ASSERT_TRUE(sph::collideBox(b, reach, top, u));
  EXPECT_EQ(top.y(), 0.5f - 0.03f);  // the roof is a side
  // Obstacles take the sides' reach.
  sph::Boundary boundary;
  boundary.spheres.push_back(sph::Sphere{Eigen::Vector3d(0.5, 0.25, 0.4), 0.1});
  Vec3 on_sphere(0.5f, 0.36f, 0.4f);
  sph::collideBoundary(boundary, b, reach, on_sphere, u);
  EXPECT_NEAR(on_sphere.y(), 0.25f + 0.1f + 0.03f, 1e-6f);
}

TEST(CollideBox, NoContactLeavesParticleUnchanged) {
  const sph::BoxState b = unitBox();
  Vec3 x(0.5f, 0.25f, 0.4f);
  Vec3 u(-3.0f, -3.0f, 3.0f);
  const Vec3 x0 = x, u0 = u;
  EXPECT_FALSE(sph::collideBox(b, kR, x, u));
  EXPECT_EQ(x, x0);
  EXPECT_EQ(u, u0);
}

// integrateAndCollide (its vectorised loop for a bare box, its general loop otherwise) must move
// and clamp as eqs. (3.21)-(3.22) and the per-particle collision functions applied in order (spheres, cylinders, box):
// particles of both classes crossing every face, fast enough to cross two at once, between moving walls; with no
// obstacle, with one out of reach, and with a sphere and two cylinders in the way (particles on the sphere's centre and
// a cylinder's axis).
class IntegrateAndCollide : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto classes = params_.levelProps();
    box_ = unitBox();
    box_.min_velocity = Vec3(0.2f, 0.0f, -0.1f);
    box_.max_velocity = Vec3(-0.3f, 0.0f, 0.05f);
    std::mt19937 rng(99);
    std::uniform_real_distribution<float> pos(-0.05f, 1.05f);
    std::uniform_real_distribution<float> speed(-8.0f, 8.0f);
    while (particles_.size() < particles_.capacity()) {
      const sph::Level c = particles_.size() % 3 == 0 ? sph::Level{1} : sph::Level{0};
      const std::uint32_t k = particles_.add(Vec3(pos(rng), pos(rng), pos(rng)),
                                             Vec3(speed(rng), speed(rng), speed(rng)), c, classes[sph::levelIndex(c)]);
      particles_.acceleration[k] = Vec3(speed(rng), speed(rng), speed(rng)) * 100.0f;
    }
    // Two particles on the sphere's centre and one on a cylinder's axis (after this step's move).
    for (std::size_t k : {0u, 1u}) place(k, Vec3(0.5f, 0.25f, 0.4f));
    place(2, Vec3(0.2f, 0.3f, 0.2f));
  }

  // Puts particle k where it will be after the step's move (zero velocity and acceleration).
  void place(std::size_t k, const Vec3& x) {
    particles_.position[k] = x;
    particles_.velocity[k] = Vec3::Zero();
    particles_.acceleration[k] = Vec3::Zero();
  }

  // Returns how many particles the obstacles touched.
  std::size_t expectStepAsPerParticleFunctions(const sph::Boundary& boundary) {
    sph::ParticleSet expected = particles_;
    const float dt = static_cast<float>(params_.time_step);
    std::size_t touched = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      Vec3 u = expected.velocity[i] + dt * expected.acceleration[i];
      Vec3 x = expected.position[i] + dt * u;
      const float r = expected.radius[i];
      bool touch = false;
      for (const sph::Sphere& s : boundary.spheres) touch |= sph::collideSphere(s, r, x, u);
      for (const sph::Cylinder& c : boundary.cylinders) touch |= sph::collideCylinder(c, r, x, u);
      touched += touch;
      sph::collideBox(box_, r, x, u);
      expected.velocity[i] = u;
      expected.position[i] = x;
    }
    sph::ParticleSet moved = particles_;
    sph::integrateAndCollide(params_, boundary, box_, moved);
    std::size_t clamped = 0;
    for (std::size_t i = 0; i < moved.size(); ++i) {
      for (int a = 0; a < 3; ++a) {
        // To float rounding: the compiler may contract v + dt a into an FMA in one loop and not
        // in the other (it does under the sanitizers with -march=native).
        EXPECT_NEAR(moved.position[i][a], expected.position[i][a], 1e-6f * (1.0f + std::abs(expected.position[i][a])))
            << "particle " << i;
        EXPECT_NEAR(moved.velocity[i][a], expected.velocity[i][a], 1e-6f * (1.0f + std::abs(expected.velocity[i][a])))
            << "particle " << i;
        clamped += expected.position[i][a] == box_.min[a] + expected.radius[i] ||
                   expected.position[i][a] == box_.max[a] - expected.radius[i];
      }
    }
    EXPECT_GT(clamped, 300u) << "the particles should cross every face";
    return touched;
  }

  sph::SimParams params_ = sph::thesisPreset();
  sph::BoxState box_;
  sph::ParticleSet particles_{2000};
};

TEST_F(IntegrateAndCollide, BareBox) { expectStepAsPerParticleFunctions(sph::Boundary{}); }

TEST_F(IntegrateAndCollide, ObstacleOutOfReach) {
  sph::Boundary boundary;
  boundary.spheres.push_back({Eigen::Vector3d(50.0, 50.0, 50.0), 0.1});
  EXPECT_EQ(expectStepAsPerParticleFunctions(boundary), 0u);
}

TEST_F(IntegrateAndCollide, SphereAndCylindersInTheWay) {
  sph::Boundary boundary;
  boundary.spheres.push_back({Eigen::Vector3d(0.5, 0.25, 0.4), 0.15});
  boundary.cylinders.push_back({0.2, 0.2, 0.05});
  boundary.cylinders.push_back({0.8, 0.6, 0.08});
  EXPECT_GT(expectStepAsPerParticleFunctions(boundary), 40u);
}

}  // namespace
