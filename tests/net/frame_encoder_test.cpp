// The frame encoder against the simulation's own arrays: both position encodings, size levels and
// their radii, counts, geometry, and reuse of one Frame object across frames of different sizes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "net/frame_encoder.h"
#include "scene/scene_loader.h"
#include "sph/simulation.h"

namespace {

sph::Scene testScene() { return scene::loadScene("tiny_pool", SPH_NET_TEST_SCENE_DIR); }

gsph::v1::Frame roundTrip(net::FrameEncoder& encoder) {
  zmq::message_t msg = encoder.serialize();
  gsph::v1::Frame parsed;
  EXPECT_TRUE(parsed.ParseFromArray(msg.data(), static_cast<int>(msg.size())));
  return parsed;
}

TEST(FrameEncoder, Float32PositionsAreTheParticlePositionsExactly) {
  sph::Simulation sim(testScene(), sph::Level{0});
  sim.step();
  net::FrameEncoder encoder;
  net::FrameInfo info;
  info.sequence = 7;
  info.scene = "tiny_pool";
  encoder.encode(sim, info);
  const gsph::v1::Frame f = roundTrip(encoder);
  const sph::ParticleSet& p = sim.particles();
  ASSERT_EQ(f.particle_count(), p.size());
  ASSERT_EQ(f.level_counts_size(), sim.params().levels);
  EXPECT_EQ(f.level_counts(0), p.size());
  EXPECT_EQ(f.level_counts(1), 0u);
  EXPECT_EQ(f.sequence(), 7u);
  EXPECT_EQ(f.step(), 1);
  EXPECT_EQ(f.protocol_version(), 1u);
  EXPECT_EQ(f.encoding(), gsph::v1::POSITION_ENCODING_FLOAT32);
  const std::vector<float> xyz = net::decodePositions(f);
  ASSERT_EQ(xyz.size(), 3 * p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int a = 0; a < 3; ++a) ASSERT_EQ(xyz[3 * i + a], p.position[i][a]) << i;
  }
  ASSERT_EQ(f.size_classes().size(), p.size());
  EXPECT_FLOAT_EQ(f.geometry().box().max().x(), 0.4f);
}

TEST(FrameEncoder, LevelRadiiAreEveryLevelsRadius) {
  sph::Simulation sim(testScene(), sph::Level{0});
  net::FrameEncoder encoder;
  encoder.encode(sim, {});
  encoder.encode(sim, {});  // a reused Frame holds the levels once
  const gsph::v1::Frame f = roundTrip(encoder);
  const auto classes = sim.params().levelProps();
  ASSERT_EQ(f.level_radii_size(), sim.params().levels);
  for (int level = 0; level < sim.params().levels; ++level) {
    EXPECT_EQ(f.level_radii(level), static_cast<float>(classes[level].radius)) << level;
  }
  EXPECT_EQ(f.radius_small(), f.level_radii(0));
  EXPECT_EQ(f.radius_large(), f.level_radii(1));
}

TEST(FrameEncoder, FoveationFiguresAndRingsAreCarriedAndClearedOnReuse) {
  sph::Simulation sim(testScene(), sph::Level{0});
  net::FrameEncoder encoder;
  net::FrameInfo info;
  info.foveation.periphery_gain_ceiling = 16.0f;
  info.foveation.visible = 900;
  info.foveation.over_budget = 12;
  info.foveation.fovea_width_arcmin = 2.5f;
  info.foveation.fovea_mar_arcmin = 1.25f;
  info.foveation.ring_radii = {0.0f, 0.02f, 0.05f};
  encoder.encode(sim, info);
  gsph::v1::Frame f = roundTrip(encoder);
  EXPECT_EQ(f.periphery_gain_ceiling(), 16.0f);
  EXPECT_EQ(f.visible_count(), 900u);
  EXPECT_EQ(f.over_budget_count(), 12u);
  EXPECT_EQ(f.fovea_width_arcmin(), 2.5f);
  EXPECT_EQ(f.fovea_mar_arcmin(), 1.25f);
  ASSERT_EQ(f.fovea_ring_radii_size(), 3);
  EXPECT_EQ(f.fovea_ring_radii(2), 0.05f);
  // Another method's frame in the same reused Frame: none of it left over.
  encoder.encode(sim, net::FrameInfo{});
  f = roundTrip(encoder);
  EXPECT_EQ(f.fovea_ring_radii_size(), 0);
  EXPECT_EQ(f.visible_count(), 0u);
  EXPECT_EQ(f.periphery_gain_ceiling(), 0.0f);
}

TEST(FrameEncoder, CountsAreLevelsZeroAndOneOnly) {
  sph::Simulation sim(testScene(), sph::Level{0});
  sph::ParticleSet& p = sim.particles();
  ASSERT_GE(p.size(), 4u);
  const auto classes = sim.params().levelProps();
  for (int level = 1; level <= 3; ++level) p.setLevel(level - 1, sph::asLevel(level), classes[level]);
  net::FrameEncoder encoder;
  encoder.encode(sim, {});
  const gsph::v1::Frame f = roundTrip(encoder);
  EXPECT_EQ(f.particle_count(), p.size());
  EXPECT_EQ(f.level_counts(0), p.size() - 3);
  for (int level = 1; level <= 3; ++level) EXPECT_EQ(f.level_counts(level), 1u) << level;
    // The deprecated pair stays for one version (sph.proto).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
  EXPECT_EQ(f.large_count(), 1u);
  EXPECT_EQ(f.small_count(), p.size() - 3);
#pragma GCC diagnostic pop
  EXPECT_EQ(f.size_classes().substr(0, 4), std::string("\x01\x02\x03\x00", 4));
}

TEST(FrameEncoder, Quantized16IsWithinOneLevelOfTheBox) {
  sph::Simulation sim(testScene(), sph::Level{1});
  sim.step();
  net::FrameEncoder encoder(net::PositionEncoding::Quantized16);
  encoder.encode(sim, {});
  const gsph::v1::Frame f = roundTrip(encoder);
  EXPECT_EQ(f.encoding(), gsph::v1::POSITION_ENCODING_QUANTIZED16);
  EXPECT_EQ(f.positions().size(), 6 * sim.particles().size());
  const sph::BoxState box = sim.boxNow();
  const std::vector<float> xyz = net::decodePositions(f);
  for (std::size_t i = 0; i < sim.particles().size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      const float level = (box.max[a] - box.min[a]) / 65535.0f;
      const float expected = std::clamp(sim.particles().position[i][a], box.min[a], box.max[a]);
      ASSERT_NEAR(xyz[3 * i + a], expected, level) << i;
    }
  }
  for (char c : f.size_classes()) EXPECT_EQ(c, 1);  // all L1
}

TEST(FrameEncoder, ReusedFrameFollowsAShrinkingParticleSet) {
  sph::Simulation big(testScene(), sph::Level{0});
  sph::Simulation small(testScene(), sph::Level{1});
  net::FrameEncoder encoder;
  encoder.setVelocities(true);
  encoder.encode(big, {});
  const gsph::v1::Frame& f = encoder.encode(small, {});
  EXPECT_EQ(f.positions().size(), 12 * small.particles().size());
  EXPECT_EQ(f.velocities().size(), 12 * small.particles().size());
  EXPECT_EQ(f.size_classes().size(), small.particles().size());
  EXPECT_EQ(f.particle_count(), small.particles().size());
}

TEST(FrameEncoder, NeighborCountsOnlyWhenAskedAndAsTheGridCountedThem) {
  sph::Simulation sim(testScene(), sph::Level{0});
  sim.step();
  net::FrameEncoder encoder;
  encoder.encode(sim, {});
  EXPECT_TRUE(roundTrip(encoder).neighbor_counts().empty());  // off by default
  encoder.setNeighborCounts(true);
  encoder.encode(sim, {});
  const gsph::v1::Frame on = roundTrip(encoder);
  const std::size_t n = sim.particles().size();
  ASSERT_EQ(on.neighbor_counts().size(), n);
  bool some_counted = false;
  for (std::size_t i = 0; i < n; ++i) {
    const auto expected = std::min<std::uint32_t>(sim.grid().neighborCount(i), 255u);
    ASSERT_EQ(static_cast<std::uint8_t>(on.neighbor_counts()[i]), expected) << i;
    some_counted = some_counted || expected > 0;
  }
  EXPECT_TRUE(some_counted);  // a resting pool: particles have neighbours
  encoder.setNeighborCounts(false);
  encoder.encode(sim, {});
  EXPECT_TRUE(roundTrip(encoder).neighbor_counts().empty());
}

TEST(FrameEncoder, MethodValuesMapBothWays) {
  for (sph::Method m : {sph::Method::Regular, sph::Method::Surface, sph::Method::Gaze, sph::Method::Hybrid}) {
    sph::Method back;
    ASSERT_TRUE(net::fromProtoMethod(net::toProtoMethod(m), back));
    EXPECT_EQ(back, m);
  }
  sph::Method out;
  EXPECT_FALSE(net::fromProtoMethod(gsph::v1::METHOD_UNSPECIFIED, out));
  EXPECT_FALSE(net::fromProtoMethod(99, out));
}

}  // namespace
