// Container over time: moving walls, box changes and the enclosing box that sizes the grid.
#include <gtest/gtest.h>

#include "sph/boundary.h"

namespace {

TEST(MovingWall, OffsetStartsAtRestAndPeaksAtHalfPeriod) {
  sph::MovingWall w{0, true, 0.2, 2.0, 1.0};
  EXPECT_EQ(w.offset(0.5), 0.0);
  EXPECT_EQ(w.velocity(0.5), 0.0);
  EXPECT_NEAR(w.offset(1.0), 0.0, 1e-12);
  EXPECT_NEAR(w.velocity(1.0), 0.0, 1e-12);
  EXPECT_NEAR(w.offset(2.0), 0.2, 1e-12);
  EXPECT_NEAR(w.offset(3.0), 0.0, 1e-12);
}

TEST(MovingWall, VelocityIsDerivativeOfOffset) {
  for (double amplitude : {0.15, -0.1}) {
    sph::MovingWall w{2, false, amplitude, 1.3, 0.4};
    const double eps = 1e-6;
    for (double t = 0.45; t < 3.0; t += 0.17) {
      const double fd = (w.offset(t + eps) - w.offset(t - eps)) / (2.0 * eps);
      EXPECT_NEAR(w.velocity(t), fd, 1e-6) << "t = " << t << ", amplitude " << amplitude;
    }
  }
}

sph::Boundary dambreak() {
  sph::Boundary b;
  b.box.min = Eigen::Vector3d(0.0, 0.0, 0.0);
  b.box.max = Eigen::Vector3d(0.4, 1.0, 0.5);
  sph::BoxChange open;
  open.time = 1.0;
  open.box.min = Eigen::Vector3d(0.0, 0.0, 0.0);
  open.box.max = Eigen::Vector3d(1.6, 1.0, 0.5);
  b.changes.push_back(open);
  return b;
}

TEST(Boundary, StateAtSwitchesBoundsAtChangeTime) {
  const sph::Boundary b = dambreak();
  EXPECT_EQ(b.stateAt(0.0).max.x(), 0.4f);
  EXPECT_EQ(b.stateAt(0.999).max.x(), 0.4f);
  EXPECT_EQ(b.stateAt(1.0).max.x(), 1.6f);
  EXPECT_EQ(b.stateAt(5.0).max.x(), 1.6f);
  EXPECT_EQ(b.stateAt(5.0).max_velocity, Eigen::Vector3f::Zero());
}

TEST(Boundary, StateAtAppliesMovingWall) {
  sph::Boundary b = dambreak();
  b.moving_walls.push_back(sph::MovingWall{0, false, 0.3, 2.0, 0.0});
  const double t = 0.7;
  const sph::BoxState s = b.stateAt(t);
  EXPECT_NEAR(s.min.x(), b.moving_walls[0].offset(t), 1e-6);
  EXPECT_NEAR(s.min_velocity.x(), b.moving_walls[0].velocity(t), 1e-6);
  EXPECT_GT(s.min_velocity.x(), 0.0f);
  EXPECT_EQ(s.max_velocity.x(), 0.0f);
}

TEST(Boundary, EnclosingBoxCoversChangesAndWallReach) {
  sph::Boundary b = dambreak();
  b.moving_walls.push_back(sph::MovingWall{1, true, 0.25, 2.0, 0.5});   // roof moves up
  b.moving_walls.push_back(sph::MovingWall{2, false, -0.2, 1.0, 0.0});  // z-min moves out
  b.moving_walls.push_back(sph::MovingWall{2, true, -0.1, 1.0, 0.0});   // z-max moves in
  const sph::Aabb all = b.enclosingBox();
  EXPECT_NEAR(all.max.x(), 1.6, 1e-12);
  EXPECT_NEAR(all.max.y(), 1.25, 1e-12);
  EXPECT_NEAR(all.min.z(), -0.2, 1e-12);
  EXPECT_NEAR(all.max.z(), 0.5, 1e-12);
  for (double t = 0.0; t < 4.0; t += 0.01) {
    const sph::BoxState s = b.stateAt(t);
    for (int a = 0; a < 3; ++a) {
      EXPECT_GE(s.min[a], all.min[a] - 1e-6) << "t = " << t << ", axis " << a;
      EXPECT_LE(s.max[a], all.max[a] + 1e-6) << "t = " << t << ", axis " << a;
    }
  }
}

}  // namespace
