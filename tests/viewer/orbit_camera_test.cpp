#include "orbit_camera.h"

#include <gtest/gtest.h>

#include <cmath>

#include "camera_reference.h"

using viewer::OrbitCamera;

TEST(OrbitCamera, LookAtAndPerspectiveMatchReference) {
  const Eigen::Vector3f eye(1.0f, 1.3f, 2.7f), target(1.0f, 0.15f, 0.4f);
  const auto view = viewer::lookAt(eye, target, Eigen::Vector3f::UnitY());
  const auto expected = viewer_test::referenceLookAt({1.0, 1.3, 2.7}, {1.0, 0.15, 0.4});
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(view.data()[i], expected[static_cast<std::size_t>(i)], 1e-5);
  const auto projection = viewer::perspective(45.0f, 16.0f / 9.0f, 0.05f, 20.0f);
  const auto expected_p = viewer_test::referencePerspective(45.0, 16.0 / 9.0, 0.05, 20.0);
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(projection.data()[i], expected_p[static_cast<std::size_t>(i)], 1e-5);
}

TEST(OrbitCamera, EyeTargetRoundTrip) {
  OrbitCamera camera;
  camera.setEyeTarget({0.3f, 1.2f, 2.0f}, {0.5f, 0.2f, 0.4f});
  EXPECT_NEAR((camera.eye() - Eigen::Vector3f(0.3f, 1.2f, 2.0f)).norm(), 0.0f, 1e-5f);
  EXPECT_NEAR((camera.target() - Eigen::Vector3f(0.5f, 0.2f, 0.4f)).norm(), 0.0f, 1e-6f);
}

TEST(OrbitCamera, OrbitKeepsDistanceAndTarget) {
  OrbitCamera camera;
  camera.setEyeTarget({0.0f, 0.5f, 2.0f}, {0.0f, 0.0f, 0.0f});
  const float d = camera.distance();
  camera.orbit(120.0f, -40.0f);
  EXPECT_NEAR((camera.eye() - camera.target()).norm(), d, 1e-5f);
  EXPECT_NEAR(camera.target().norm(), 0.0f, 1e-6f);
  EXPECT_GT((camera.eye() - Eigen::Vector3f(0.0f, 0.5f, 2.0f)).norm(), 0.1f);
}

TEST(OrbitCamera, ZoomAndPan) {
  OrbitCamera camera;
  camera.setEyeTarget({0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, 0.0f});
  camera.zoom(1.0f);
  EXPECT_NEAR(camera.distance(), 1.8f, 1e-5f);
  // panning right by a few pixels moves the target to -x (the scene follows the cursor)
  camera.pan(10.0f, 0.0f, 720);
  EXPECT_LT(camera.target().x(), 0.0f);
  EXPECT_NEAR(camera.target().y(), 0.0f, 1e-6f);
}

TEST(OrbitCamera, AdoptViewRecoversEye) {
  const Eigen::Vector3f eye(1.0f, 1.3f, 2.7f), target(1.0f, 0.15f, 0.4f);
  OrbitCamera camera;
  ASSERT_TRUE(camera.adoptView(viewer::lookAt(eye, target, Eigen::Vector3f::UnitY()), (target - eye).norm()));
  EXPECT_NEAR((camera.eye() - eye).norm(), 0.0f, 1e-4f);
  EXPECT_NEAR((camera.target() - target).norm(), 0.0f, 1e-4f);
  Eigen::Matrix4f bad = Eigen::Matrix4f::Identity() * 3.0f;
  EXPECT_FALSE(camera.adoptView(bad, 1.0f));
}
