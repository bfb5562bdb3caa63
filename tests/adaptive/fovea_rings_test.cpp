// The rings where the foveated method's coarser levels begin around the gaze (adaptive/fovea_rings.h):
// the screen points a ring passes through are seen at the eccentricity where the acuity rule first
// allows the level, and the rings move as the rule says they must with e, q and g.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include <Eigen/Geometry>

#include "sph/adaptive/fovea_rings.h"

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

// The angle, degrees, between the directions through two screen points, as foveated.cpp measures it.
double angleBetween(double tan_half, double aspect, double x0, double y0, double x1, double y1) {
  const Eigen::Vector3d a((2 * x0 - 1) * tan_half, (1 - 2 * y0) * tan_half / aspect, 1);
  const Eigen::Vector3d b((2 * x1 - 1) * tan_half, (1 - 2 * y1) * tan_half / aspect, 1);
  return kDeg * std::atan2(a.cross(b).norm(), a.dot(b));
}

sph::AdaptiveConfig config(double q, double g) {
  sph::AdaptiveConfig c;
  c.foveated_quality = q;
  c.foveated_periphery_gain = g;
  return c;
}

TEST(FoveaRings, OnsetIsWhereTheAcuityRuleFirstAllowsTheLevel) {
  const sph::AdaptiveConfig c = config(1.5, 2.0);
  for (const double width : {2.0, 4.0, 8.0}) {
    const double e = sph::levelOnsetEccentricityDeg(c, width);
    const double allowed =
        c.foveated_quality * (1 + c.foveated_periphery_gain * c.foveated_mar_slope / c.foveated_mar_w0_deg * e);
    EXPECT_NEAR(allowed, width, 1e-9 * width);
  }
  // q alone allows a level no wider than q at the gaze point: no ring.
  EXPECT_EQ(sph::levelOnsetEccentricityDeg(c, 1.5), 0.0);
  EXPECT_EQ(sph::levelOnsetEccentricityDeg(c, 1.2), 0.0);
}

TEST(FoveaRings, AtTheScreenCentreTheRingIsTheExactCircle) {
  const double tan_half = std::tan(20.0 / kDeg);
  for (const double e : {0.5, 5.0, 15.0}) {
    EXPECT_NEAR(sph::eccentricityRadiusOnScreen(e, tan_half, 0.5, 0.5), std::tan(e / kDeg) / (2 * tan_half), 1e-9);
  }
}

TEST(FoveaRings, OffCentreTheRingPassesNearPointsSeenAtItsEccentricity) {
  // Off centre the points at e form a conic: the circle of the mean distance lies between its
  // nearest and farthest points, and each point it passes through is seen within a tenth of e.
  const double tan_half = std::tan(20.0 / kDeg);
  const double aspect = 16.0 / 9.0;
  const double gx = 0.8, gy = 0.3, e = 6.0;
  const double r = sph::eccentricityRadiusOnScreen(e, tan_half, gx, gy);
  ASSERT_GT(r, 0.0);
  for (int i = 0; i < 16; ++i) {
    const double theta = 2 * std::numbers::pi * i / 16;
    const double x = gx + r * std::cos(theta);
    const double y = gy + r * std::sin(theta) * aspect;  // r is in widths; y in heights
    EXPECT_NEAR(angleBetween(tan_half, aspect, gx, gy, x, y), e, 0.1 * e) << "direction " << i;
  }
}

TEST(FoveaRings, RadiusGrowsWithEccentricity) {
  const double tan_half = std::tan(20.0 / kDeg);
  double last = 0.0;
  for (double e = 0.5; e < 60.0; e += 0.5) {
    const double r = sph::eccentricityRadiusOnScreen(e, tan_half, 0.3, 0.6);
    EXPECT_GT(r, last) << e;
    last = r;
  }
  // Beyond what the display's plane reaches in any direction: off any screen.
  EXPECT_EQ(sph::eccentricityRadiusOnScreen(120.0, tan_half, 0.5, 0.5), sph::kOffScreenRingRadius);
}

TEST(FoveaRings, RingsWidenAsQualityAndGainFall) {
  const std::vector<double> widths{1.0, 2.0, 4.0, 8.0};
  const double tan_half = std::tan(20.0 / kDeg);
  const auto fine = sph::foveaRingRadii(config(1.0, 1.0), widths, tan_half, 0.5, 0.5);
  const auto coarse_q = sph::foveaRingRadii(config(1.5, 1.0), widths, tan_half, 0.5, 0.5);
  const auto coarse_g = sph::foveaRingRadii(config(1.0, 4.0), widths, tan_half, 0.5, 0.5);
  ASSERT_EQ(fine.size(), 3u);
  ASSERT_EQ(coarse_q.size(), 3u);
  for (std::size_t k = 0; k < fine.size(); ++k) {
    EXPECT_GT(fine[k], coarse_q[k]) << "L" << k + 1;
    EXPECT_GT(fine[k], coarse_g[k]) << "L" << k + 1;
    if (k > 0) {
      EXPECT_GT(fine[k], fine[k - 1]) << "coarser levels begin farther out";
    }
  }
  // A level no wider than q is allowed at the gaze point: its ring has radius 0.
  const auto at_gaze = sph::foveaRingRadii(config(2.5, 1.0), widths, tan_half, 0.5, 0.5);
  EXPECT_EQ(at_gaze[0], 0.0f);
  EXPECT_GT(at_gaze[1], 0.0f);
}

}  // namespace
