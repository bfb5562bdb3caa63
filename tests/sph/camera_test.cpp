// Projection of particle centres and radii to normalized screen coordinates (thesis 3.6.4).
#include <gtest/gtest.h>

#include <cmath>

#include "sph/camera.h"

namespace {

sph::ScreenCamera testCamera() {
  sph::CameraSpec spec;
  spec.eye = Eigen::Vector3d(0.0, 0.0, 5.0);
  spec.target = Eigen::Vector3d::Zero();
  spec.up = Eigen::Vector3d::UnitY();
  spec.fov_y_degrees = 60.0;
  spec.viewport_width = 1600;
  spec.viewport_height = 800;
  return sph::cameraFromSpec(spec);
}

TEST(Camera, TargetProjectsToTheScreenCentre) {
  const sph::Projector proj(testCamera());
  const sph::ScreenDisc d = proj.project(Eigen::Vector3d::Zero(), 0.1);
  ASSERT_TRUE(d.in_front);
  EXPECT_NEAR(d.x, 0.5, 1e-12);
  EXPECT_NEAR(d.y, 0.5, 1e-12);
}

TEST(Camera, ScreenOriginIsTopLeft) {
  const sph::Projector proj(testCamera());
  const sph::ScreenDisc up = proj.project(Eigen::Vector3d(0.0, 1.0, 0.0), 0.1);
  const sph::ScreenDisc right = proj.project(Eigen::Vector3d(1.0, 0.0, 0.0), 0.1);
  EXPECT_LT(up.y, 0.5);
  EXPECT_NEAR(up.x, 0.5, 1e-12);
  EXPECT_GT(right.x, 0.5);
  EXPECT_NEAR(right.y, 0.5, 1e-12);
  // tan(30 deg) * 5 is the half-height of the view at the target's depth: y = 1 is 1/2.887 of it.
  const double half_height = std::tan(M_PI / 6.0) * 5.0;
  EXPECT_NEAR(up.y, 0.5 - 0.5 / half_height, 1e-9);
}

TEST(Camera, ProjectedRadiusIsAFractionOfTheWidth) {
  const sph::Projector proj(testCamera());
  const double r = 0.05;
  const sph::ScreenDisc d = proj.project(Eigen::Vector3d::Zero(), r);
  // Half-height of the view at depth 5 covers 400 px; width is 1600 px.
  const double half_height = std::tan(M_PI / 6.0) * 5.0;
  EXPECT_NEAR(d.radius, r / half_height * 400.0 / 1600.0, 1e-12);
  // The same as projecting a point on the sphere's rim beside the centre.
  const sph::ScreenDisc rim = proj.project(Eigen::Vector3d(r, 0.0, 0.0), r);
  EXPECT_NEAR(rim.x - d.x, d.radius, 1e-9);
}

TEST(Camera, PointsBehindTheEyeAreNotInFront) {
  const sph::Projector proj(testCamera());
  EXPECT_FALSE(proj.project(Eigen::Vector3d(0.0, 0.0, 6.0), 0.1).in_front);
  EXPECT_FALSE(proj.projectFast(Eigen::Vector3f(0.0f, 0.0f, 6.0f), 0.1f).in_front);
}

TEST(Camera, SinglePrecisionProjectionAgreesWithDouble) {
  const sph::Projector proj(testCamera());
  for (int k = 0; k < 200; ++k) {
    // A spiral of points through the view volume, near and far.
    const Eigen::Vector3f p(1.5f * std::sin(0.7f * k), 1.0f * std::cos(0.9f * k), 3.0f - 0.04f * k);
    const sph::ScreenDisc d = proj.project(p.cast<double>(), 0.03);
    const sph::FastScreenDisc f = proj.projectFast(p, 0.03f);
    ASSERT_EQ(f.in_front != 0, d.in_front) << "point " << k;
    EXPECT_NEAR(f.x, d.x, 1e-5) << "point " << k;
    EXPECT_NEAR(f.y, d.y, 1e-5) << "point " << k;
    EXPECT_NEAR(f.radius, d.radius, 1e-6 + 1e-5 * d.radius) << "point " << k;
  }
}

TEST(Camera, UnusableCamerasAreRecognised) {
  sph::ScreenCamera cam = testCamera();
  EXPECT_TRUE(sph::isUsable(cam));
  cam.view(0, 0) = std::nan("");
  EXPECT_FALSE(sph::isUsable(cam));
  cam = testCamera();
  cam.viewport_width = 0;
  EXPECT_FALSE(sph::isUsable(cam));
}

}  // namespace
