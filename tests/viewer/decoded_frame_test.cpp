#include "decoded_frame.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "test_frames.h"

using viewer::DecodedFrame;
using viewer::decodeFrame;
using viewer_test::FrameSpec;
using viewer_test::makeFrame;

namespace {
FrameSpec threeParticles() {
  FrameSpec spec;
  spec.particles = {{0.1f, 0.2f, 0.3f, 0}, {-0.5f, 0.25f, 0.75f, 1}, {0.9f, -0.9f, 0.0f, 1}};
  return spec;
}

FrameSpec fourLevels() {
  FrameSpec spec;
  spec.particles = {{0.1f, 0.1f, 0.1f, 0}, {0.2f, 0.2f, 0.2f, 1}, {0.3f, 0.3f, 0.3f, 2},
                    {0.4f, 0.4f, 0.4f, 3}, {0.5f, 0.5f, 0.5f, 3}, {0.6f, 0.6f, 0.6f, 0}};
  spec.radius_small = 0.01f;
  spec.radius_large = 0.0126f;
  spec.level_radii = {0.01f, 0.0126f, 0.0159f, 0.02f};
  return spec;
}
}  // namespace

TEST(DecodedFrame, FloatPositionsAndClasses) {
  DecodedFrame out;
  std::string error;
  ASSERT_TRUE(decodeFrame(makeFrame(threeParticles(), 7), out, error)) << error;
  ASSERT_EQ(out.particleCount(), 3u);
  EXPECT_FLOAT_EQ(out.positions[1].x, -0.5f);
  EXPECT_FLOAT_EQ(out.positions[1].z, 0.75f);
  EXPECT_EQ(out.classes[0], viewer::kClassSmall);
  EXPECT_EQ(out.level_counts, (std::vector<std::uint32_t>{1, 2}));
  EXPECT_EQ(out.sequence, 7u);
  EXPECT_TRUE(out.geometry.has_box);
  EXPECT_FLOAT_EQ(out.radius_large, 0.05f);
}

TEST(DecodedFrame, QuantizedMatchesFloatWithinOneStep) {
  FrameSpec spec = threeParticles();
  DecodedFrame as_float, as_quantized;
  std::string error;
  ASSERT_TRUE(decodeFrame(makeFrame(spec, 1), as_float, error)) << error;
  spec.quantized = true;
  ASSERT_TRUE(decodeFrame(makeFrame(spec, 1), as_quantized, error)) << error;
  ASSERT_EQ(as_quantized.encoding, gsph::v1::POSITION_ENCODING_QUANTIZED16);
  const float step = 2.0f / 65535.0f;  // box side / (2^16 - 1)
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(as_quantized.positions[i].x, as_float.positions[i].x, step);
    EXPECT_NEAR(as_quantized.positions[i].y, as_float.positions[i].y, step);
    EXPECT_NEAR(as_quantized.positions[i].z, as_float.positions[i].z, step);
  }
}

TEST(DecodedFrame, QuantizedEndsMapToBoxCorners) {
  FrameSpec spec;
  spec.particles = {{-1.0f, -1.0f, -1.0f, 0}, {1.0f, 1.0f, 1.0f, 1}};
  spec.quantized = true;
  DecodedFrame out;
  std::string error;
  ASSERT_TRUE(decodeFrame(makeFrame(spec, 1), out, error)) << error;
  EXPECT_FLOAT_EQ(out.positions[0].x, -1.0f);
  EXPECT_NEAR(out.positions[1].y, 1.0f, 1e-6f);
}

TEST(DecodedFrame, SpeedsFromVelocities) {
  FrameSpec spec = threeParticles();
  spec.with_velocities = true;
  DecodedFrame out;
  std::string error;
  ASSERT_TRUE(decodeFrame(makeFrame(spec, 1), out, error)) << error;
  ASSERT_EQ(out.speeds.size(), 3u);
  EXPECT_NEAR(out.speeds[2], 0.2f, 1e-6f);
}

TEST(DecodedFrame, NeighborCountsWhenPresentOnePerParticle) {
  FrameSpec spec = threeParticles();
  DecodedFrame out;
  std::string error;
  ASSERT_TRUE(decodeFrame(makeFrame(spec, 1), out, error)) << error;
  EXPECT_TRUE(out.neighbor_counts.empty());
  spec.neighbor_counts = {0, 17, 255};
  ASSERT_TRUE(decodeFrame(makeFrame(spec, 1), out, error)) << error;
  EXPECT_EQ(out.neighbor_counts, (std::vector<std::uint8_t>{0, 17, 255}));
  spec.neighbor_counts = {3, 4};
  EXPECT_FALSE(decodeFrame(makeFrame(spec, 1), out, error));
  EXPECT_NE(error.find("neighbor_counts"), std::string::npos);
}

TEST(DecodedFrame, RejectsWrongVersion) {
  auto frame = makeFrame(threeParticles(), 1);
  frame.set_protocol_version(2);
  DecodedFrame out;
  std::string error;
  EXPECT_FALSE(decodeFrame(frame, out, error));
  EXPECT_NE(error.find("protocol_version"), std::string::npos);
}

TEST(DecodedFrame, RejectsTruncatedPositions) {
  auto frame = makeFrame(threeParticles(), 1);
  frame.mutable_positions()->resize(frame.positions().size() - 1);
  DecodedFrame out;
  std::string error;
  EXPECT_FALSE(decodeFrame(frame, out, error));
  EXPECT_NE(error.find("positions"), std::string::npos);
}

TEST(DecodedFrame, RejectsCountMismatchAndBadClass) {
  auto frame = makeFrame(threeParticles(), 1);
  frame.set_particle_count(4);
  DecodedFrame out;
  std::string error;
  EXPECT_FALSE(decodeFrame(frame, out, error));
  frame = makeFrame(threeParticles(), 1);
  (*frame.mutable_size_classes())[1] = 7;
  EXPECT_FALSE(decodeFrame(frame, out, error));
  EXPECT_NE(error.find("size class 7"), std::string::npos);
}

TEST(DecodedFrame, SizeLevelsTakeTheirRadiiFromLevelRadii) {
  DecodedFrame out;
  std::string error;
  ASSERT_TRUE(decodeFrame(makeFrame(fourLevels(), 1), out, error)) << error;
  EXPECT_EQ(out.classes, (std::vector<std::uint8_t>{0, 1, 2, 3, 3, 0}));
  EXPECT_EQ(out.level_radii, (std::vector<float>{0.01f, 0.0126f, 0.0159f, 0.02f}));
  EXPECT_EQ(out.level_counts, (std::vector<std::uint32_t>{2, 1, 1, 2}));
  EXPECT_TRUE(out.hasExtraLevels());
}

TEST(DecodedFrame, TwoClassFrameWithoutLevelRadiiTakesRadiusSmallAndLarge) {
  DecodedFrame out;
  std::string error;
  ASSERT_TRUE(decodeFrame(makeFrame(threeParticles(), 1), out, error)) << error;
  EXPECT_EQ(out.level_radii, (std::vector<float>{0.04f, 0.05f}));
  EXPECT_EQ(out.level_counts, (std::vector<std::uint32_t>{1, 2}));
  EXPECT_FALSE(out.hasExtraLevels());
}

TEST(DecodedFrame, RejectsALevelBeyondLevelRadii) {
  FrameSpec spec = fourLevels();
  spec.level_radii.resize(3);
  DecodedFrame out;
  std::string error;
  EXPECT_FALSE(decodeFrame(makeFrame(spec, 1), out, error));
  EXPECT_NE(error.find("size level 3 is beyond the 3 levels"), std::string::npos) << error;
  spec.level_radii.clear();  // a two-class frame: levels 2 and 3 are unknown
  EXPECT_FALSE(decodeFrame(makeFrame(spec, 1), out, error));
  EXPECT_NE(error.find("size class 2 is neither L0 (0) nor L1 (1)"), std::string::npos) << error;
}

TEST(DecodedFrame, RejectsBadLevelRadii) {
  FrameSpec spec = fourLevels();
  spec.level_radii[2] = std::numeric_limits<float>::infinity();
  DecodedFrame out;
  std::string error;
  EXPECT_FALSE(decodeFrame(makeFrame(spec, 1), out, error));
  EXPECT_NE(error.find("level_radii[2]"), std::string::npos) << error;
  spec.level_radii[2] = -0.01f;
  EXPECT_FALSE(decodeFrame(makeFrame(spec, 1), out, error));
  EXPECT_NE(error.find("level_radii[2]"), std::string::npos) << error;
  spec = fourLevels();
  spec.level_radii.assign(viewer::kMaxSizeLevels + 1, 0.01f);
  EXPECT_FALSE(decodeFrame(makeFrame(spec, 1), out, error));
  EXPECT_NE(error.find("17 size levels"), std::string::npos) << error;
  spec.level_radii.resize(viewer::kMaxSizeLevels);
  EXPECT_TRUE(decodeFrame(makeFrame(spec, 1), out, error)) << error;
}

TEST(DecodedFrame, RejectsNonFinitePositionAndMissingQuantizationBox) {
  auto frame = makeFrame(threeParticles(), 1);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  frame.mutable_positions()->replace(0, sizeof(float), reinterpret_cast<const char*>(&nan), sizeof(float));
  DecodedFrame out;
  std::string error;
  EXPECT_FALSE(decodeFrame(frame, out, error));
  FrameSpec spec = threeParticles();
  spec.quantized = true;
  frame = makeFrame(spec, 1);
  frame.clear_quantization_box();
  EXPECT_FALSE(decodeFrame(frame, out, error));
}

TEST(DecodedFrame, RejectsUnknownEncodingAndGarbageBytes) {
  auto frame = makeFrame(threeParticles(), 1);
  frame.set_encoding(static_cast<gsph::v1::PositionEncoding>(9));
  DecodedFrame out;
  std::string error;
  EXPECT_FALSE(decodeFrame(frame, out, error));
  const char garbage[] = "\xff\xff\xff\xff not a frame";
  EXPECT_FALSE(viewer::decodeFrameBytes(garbage, sizeof(garbage), out, error));
}

TEST(DecodedFrame, EmptyFrameIsValid) {
  FrameSpec spec;
  DecodedFrame out;
  std::string error;
  EXPECT_TRUE(decodeFrame(makeFrame(spec, 1), out, error)) << error;
  EXPECT_EQ(out.particleCount(), 0u);
}
