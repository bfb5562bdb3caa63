// Every check on untrusted input, one at a time: a message with one bad field is refused with a reason.
#include <gtest/gtest.h>

#include <limits>

#include "net/input_validation.h"
#include "net_test_util.h"

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

gsph::v1::GazeSample goodGaze() {
  gsph::v1::GazeSample g;
  g.set_protocol_version(1);
  g.set_x(0.25f);
  g.set_y(0.75f);
  g.set_valid(true);
  g.set_confidence(0.9f);
  return g;
}

std::string checkGaze(const gsph::v1::GazeSample& g) {
  const std::string bytes = g.SerializeAsString();
  gsph::v1::GazeSample out;
  return net::parseGazeSample(bytes.data(), bytes.size(), out);
}

gsph::v1::CameraPose goodPose() {
  gsph::v1::CameraPose p;
  p.set_protocol_version(1);
  p.set_viewer_id("v");
  net::fromScreenCamera(sph::ScreenCamera{}, p);
  return p;
}

std::string checkPose(const gsph::v1::CameraPose& p) {
  const std::string bytes = p.SerializeAsString();
  gsph::v1::CameraPose out;
  return net::parseCameraPose(bytes.data(), bytes.size(), out);
}

TEST(InputValidation, GoodGazeIsAccepted) { EXPECT_EQ(checkGaze(goodGaze()), ""); }

TEST(InputValidation, GazeWithBadFieldsIsRefused) {
  auto g = goodGaze();
  g.set_x(kNaN);
  EXPECT_NE(checkGaze(g), "");
  g = goodGaze();
  g.set_y(1.5f);
  EXPECT_NE(checkGaze(g), "");
  g = goodGaze();
  g.set_confidence(-0.1f);
  EXPECT_NE(checkGaze(g), "");
  g = goodGaze();
  g.set_protocol_version(2);
  EXPECT_NE(checkGaze(g), "");
  g = goodGaze();
  g.set_source_id(std::string(500, 'a'));
  EXPECT_NE(checkGaze(g), "");
}

TEST(InputValidation, InvalidOrLostGazeNeedsNoPoint) {
  auto g = goodGaze();
  g.set_valid(false);
  g.set_x(kNaN);
  EXPECT_EQ(checkGaze(g), "");
  g = goodGaze();
  g.set_lost(true);
  g.set_x(-3.0f);
  EXPECT_EQ(checkGaze(g), "");
}

TEST(InputValidation, GarbageAndTruncatedBytesAreRefused) {
  gsph::v1::GazeSample g;
  const std::string garbage = "\xff\xff\xff\xff\xff\xff garbage";
  EXPECT_NE(net::parseGazeSample(garbage.data(), garbage.size(), g), "");
  const std::string bytes = goodPose().SerializeAsString();
  gsph::v1::CameraPose p;
  EXPECT_NE(net::parseCameraPose(bytes.data(), bytes.size() / 2, p), "");
}

TEST(InputValidation, PoseChecksMatricesAndViewport) {
  EXPECT_EQ(checkPose(goodPose()), "");
  auto p = goodPose();
  p.mutable_view()->RemoveLast();
  EXPECT_NE(checkPose(p), "");
  p = goodPose();
  p.set_projection(5, kNaN);
  EXPECT_NE(checkPose(p), "");
  p = goodPose();
  for (int i = 0; i < 16; ++i) p.set_projection(i, 0.0f);
  EXPECT_NE(checkPose(p), "") << "singular projection";
  p = goodPose();
  p.set_viewport_width(0);
  EXPECT_NE(checkPose(p), "");
  p = goodPose();
  p.set_viewport_height(100000);
  EXPECT_NE(checkPose(p), "");
}

TEST(InputValidation, PoseRoundTripsThroughScreenCamera) {
  sph::ScreenCamera c;
  c.view = sph::lookAt({1, 2, 3}, {0, 0, 0}, {0, 1, 0});
  c.projection = sph::perspective(50, 1.5, 0.1, 10);
  c.viewport_width = 1500;
  c.viewport_height = 1000;
  gsph::v1::CameraPose p;
  net::fromScreenCamera(c, p);
  const sph::ScreenCamera back = net::toScreenCamera(p);
  EXPECT_LT(net_test::maxAbsDiff(back.view, c.view), 1e-6);
  EXPECT_LT(net_test::maxAbsDiff(back.projection, c.projection), 1e-6);
  EXPECT_EQ(back.viewport_width, 1500);
}

TEST(InputValidation, ControlNeedsVersionAndCommand) {
  gsph::v1::Control c;
  c.set_protocol_version(1);
  std::string bytes = c.SerializeAsString();
  gsph::v1::Control out;
  EXPECT_NE(net::parseControl(bytes.data(), bytes.size(), out), "");
  c.mutable_status();
  bytes = c.SerializeAsString();
  EXPECT_EQ(net::parseControl(bytes.data(), bytes.size(), out), "");
  c.set_protocol_version(0);
  bytes = c.SerializeAsString();
  EXPECT_NE(net::parseControl(bytes.data(), bytes.size(), out), "");
}

}  // namespace
