// dfsph's floor as a constraint of its constant-density solve (floor_contact.h): which particles
// the floor holds, what of their velocity and acceleration it removes, and their slip.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "sph/params.h"
#include "sph/particles.h"
#include "sph/solvers/floor_contact.h"

namespace {

using sph::Vec3;

constexpr float kDt = 0.004f;
constexpr float kSpacing = 0.02f;

// A 1 m box; the floor's guard at half a spacing, the sides' at 0.3 spacings (dfsph's).
struct FloorBox {
  sph::BoxState box;
  std::array<sph::WallReach, sph::kMaxLevels> reach{};
  std::array<float, sph::kMaxLevels> spacing{};
  sph::ParticleSet particles{16};
  sph::LevelProps props = sph::SimParams{}.levelProps()[0];

  FloorBox() {
    box.min = Eigen::Vector3f::Zero();
    box.max = Eigen::Vector3f::Ones();
    reach.fill(sph::WallReach(0.5f * kSpacing, 0.3f * kSpacing));
    spacing.fill(kSpacing);
  }
  std::size_t add(const Vec3& x, const Vec3& u) { return particles.add(x, u, sph::Level{0}, props); }
};

TEST(FloorContact, HoldsWhatReachesTheFloorsGuardWithinTheStep) {
  FloorBox s;
  const float guard = 0.5f * kSpacing;
  const std::size_t resting = s.add(Vec3(0.5f, guard, 0.5f), Vec3(0.1f, -0.05f, 0.0f));
  const std::size_t landing = s.add(Vec3(0.4f, guard + 0.5f * kDt, 0.4f), Vec3(0.0f, -1.0f, 0.0f));
  const std::size_t above = s.add(Vec3(0.3f, guard + 0.1f * kSpacing, 0.3f), Vec3(0.0f, -0.1f, 0.0f));
  const std::size_t rising = s.add(Vec3(0.6f, guard, 0.6f), Vec3(0.0f, 0.2f, 0.0f));
  sph::FloorContact floor;
  floor.find(s.particles, s.box, s.reach, s.spacing, kDt);
  // Velocity into the floor removed, along it kept (until the slip relaxes, below).
  EXPECT_EQ(s.particles.velocity[resting], Vec3(0.1f, 0.0f, 0.0f));
  EXPECT_EQ(s.particles.velocity[landing], Vec3::Zero());
  EXPECT_EQ(s.particles.velocity[above], Vec3(0.0f, -0.1f, 0.0f));  // ends the step 1.6 mm above the guard
  EXPECT_EQ(s.particles.velocity[rising], Vec3(0.0f, 0.2f, 0.0f));

  std::vector<Vec3> acceleration(s.particles.size(), Vec3(1.0f, -2.0f, 3.0f));
  floor.hold(acceleration);
  EXPECT_EQ(acceleration[resting], Vec3(1.0f, 0.0f, 3.0f));
  EXPECT_EQ(acceleration[landing], Vec3(1.0f, 0.0f, 3.0f));
  EXPECT_EQ(acceleration[above], Vec3(1.0f, -2.0f, 3.0f));
  EXPECT_EQ(acceleration[rising], Vec3(1.0f, -2.0f, 3.0f));
}

TEST(FloorContact, HoldsAnEdgeAlongTheSideWallToo) {
  FloorBox s;
  const float floor_guard = 0.5f * kSpacing;
  const float side_guard = 0.3f * kSpacing;
  const std::size_t edge = s.add(Vec3(side_guard, floor_guard, 0.5f), Vec3(-0.2f, -0.1f, 0.3f));
  const std::size_t corner = s.add(Vec3(1.0f - side_guard, floor_guard, side_guard), Vec3(0.2f, 0.0f, -0.1f));
  // At a side wall but off the floor: free (a side layer leaves its wall and comes back).
  const std::size_t side = s.add(Vec3(side_guard, 0.3f, 0.5f), Vec3(-0.2f, -0.1f, 0.0f));
  sph::FloorContact floor;
  floor.find(s.particles, s.box, s.reach, s.spacing, kDt);
  EXPECT_EQ(s.particles.velocity[edge], Vec3(0.0f, 0.0f, 0.3f));
  EXPECT_EQ(s.particles.velocity[corner], Vec3::Zero());
  EXPECT_EQ(s.particles.velocity[side], Vec3(-0.2f, -0.1f, 0.0f));

  std::vector<Vec3> acceleration(s.particles.size(), Vec3(1.0f, -2.0f, 3.0f));
  floor.hold(acceleration);
  EXPECT_EQ(acceleration[edge], Vec3(0.0f, 0.0f, 3.0f));
  EXPECT_EQ(acceleration[corner], Vec3::Zero());
  EXPECT_EQ(acceleration[side], Vec3(1.0f, -2.0f, 3.0f));
}

TEST(FloorContact, RelaxesTheSlipOfTheHeldAlone) {
  FloorBox s;
  const std::size_t held = s.add(Vec3(0.5f, 0.5f * kSpacing, 0.5f), Vec3(0.1f, 0.0f, -0.2f));
  const std::size_t free = s.add(Vec3(0.5f, 0.5f, 0.5f), Vec3(0.1f, 0.0f, -0.2f));
  sph::FloorContact floor;
  floor.find(s.particles, s.box, s.reach, s.spacing, kDt);
  floor.relaxSlip(s.particles);
  const Vec3 slowed = s.particles.velocity[held];
  EXPECT_GT(slowed.x(), 0.0f);
  EXPECT_LT(slowed.x(), 0.1f);
  EXPECT_FLOAT_EQ(slowed.z() / slowed.x(), -2.0f);  // along the slip, not turned
  EXPECT_EQ(s.particles.velocity[free], Vec3(0.1f, 0.0f, -0.2f));
}

}  // namespace
