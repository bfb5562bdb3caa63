// Checkpoint and restart (sph/checkpoint.h): a run saved after N steps and continued in a fresh
// simulation equals the uninterrupted run bit for bit, for every preset and with an adaptive
// method splitting and merging; a bad file is refused with a clear reason and changes nothing.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "sph/adaptive/adaptive_controller.h"
#include "sph/camera.h"
#include "sph/checkpoint.h"
#include "sph/simulation.h"
#include "support/box_scene.h"

namespace {

sph::Scene tank(const std::string& preset) {
  // A dam break: the water moves.
  return sph_test::boxScene("checkpoint_test", preset, {0.4, 0.5, 0.4}, {0.0, 0.0, 0.0}, {0.2, 0.3, 0.4}, 600);
}

std::unique_ptr<sph::Simulation> makeSim(const sph::Scene& scene, sph::Method method) {
  auto sim = std::make_unique<sph::Simulation>(scene, sph::startLevel(method, scene.params.levels), 4000);
  if (method != sph::Method::Regular) {
    sim->setAdaptiveStep(sph::makeAdaptiveController(method, scene.params.levels, sph::AdaptiveConfig{},
                                                     sph::cameraFromSpec(scene.camera)));
  }
  return sim;
}

std::string tempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("sph_checkpoint_" + name + "_" + std::to_string(::getpid())))
      .string();
}

// Every attribute, byte for byte.
std::string stateBytes(const sph::ParticleSet& p) {
  std::string bytes;
  p.forEachAttribute([&](const auto& values) {
    bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(values[0]));
  });
  return bytes;
}

struct Case {
  const char* preset;
  sph::Method method;
};

class CheckpointRestart : public ::testing::TestWithParam<Case> {};

TEST_P(CheckpointRestart, ContinuedRunEqualsUninterruptedBitForBit) {
  const auto [preset, method] = GetParam();
  const sph::Scene scene = tank(preset);
  // 13 and 11 steps: the cut falls between two re-sorts (resort_interval 8), the harder case.
  constexpr int kBefore = 13, kAfter = 11;
  auto uninterrupted = makeSim(scene, method);
  for (int s = 0; s < kBefore + kAfter; ++s) uninterrupted->step();

  const std::string path = tempPath(preset);
  {
    auto first = makeSim(scene, method);
    for (int s = 0; s < kBefore; ++s) first->step();
    sph::saveCheckpoint(*first, sph::methodName(method), path);
  }
  auto resumed = makeSim(scene, method);
  const sph::CheckpointInfo info = sph::loadCheckpoint(*resumed, sph::methodName(method), path);
  std::filesystem::remove(path);
  EXPECT_EQ(info.steps, kBefore);
  EXPECT_EQ(resumed->stepCount(), kBefore);
  for (int s = 0; s < kAfter; ++s) resumed->step();

  EXPECT_EQ(resumed->stepCount(), uninterrupted->stepCount());
  EXPECT_EQ(resumed->time(), uninterrupted->time());
  ASSERT_EQ(resumed->particles().size(), uninterrupted->particles().size());
  EXPECT_EQ(resumed->particles().id, uninterrupted->particles().id);
  EXPECT_TRUE(stateBytes(resumed->particles()) == stateBytes(uninterrupted->particles()));
  EXPECT_EQ(resumed->particles().nextId(), uninterrupted->particles().nextId());
}

INSTANTIATE_TEST_SUITE_P(Presets, CheckpointRestart,
                         ::testing::Values(Case{"thesis", sph::Method::Regular}, Case{"thesis", sph::Method::Surface},
                                           Case{"pbf", sph::Method::Regular}, Case{"pbf", sph::Method::Surface},
                                           Case{"dfsph", sph::Method::Regular}),
                         [](const auto& param_info) {
                           return std::string(param_info.param.preset) + "_" + sph::methodName(param_info.param.method);
                         });

class CheckpointRefusal : public ::testing::Test {
 protected:
  void SetUp() override {
    saved_ = makeSim(tank("pbf"), sph::Method::Regular);
    for (int s = 0; s < 3; ++s) saved_->step();
    sph::saveCheckpoint(*saved_, "regular", path_);
    std::ifstream in(path_, std::ios::binary);
    bytes_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  void TearDown() override { std::filesystem::remove(path_); }

  void write(const std::string& bytes) {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out << bytes;
  }
  // Loading must throw a CheckpointError whose text contains `why`, and leave `target` unchanged.
  void expectRefused(sph::Simulation& target, const std::string& method, const std::string& why) {
    const std::string before = stateBytes(target.particles());
    const auto steps = target.stepCount();
    try {
      sph::loadCheckpoint(target, method, path_);
      ADD_FAILURE() << "loaded; expected a refusal mentioning '" << why << "'";
    } catch (const sph::CheckpointError& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
    EXPECT_TRUE(stateBytes(target.particles()) == before);
    EXPECT_EQ(target.stepCount(), steps);
  }

  std::string path_ = tempPath("refusal");
  std::unique_ptr<sph::Simulation> saved_;
  std::string bytes_;
};

TEST_F(CheckpointRefusal, OtherPresetSceneOrMethod) {
  auto dfsph = makeSim(tank("dfsph"), sph::Method::Regular);
  expectRefused(*dfsph, "regular", "preset 'pbf'");
  sph::Scene other = tank("pbf");
  other.name = "another_scene";
  auto elsewhere = makeSim(other, sph::Method::Regular);
  expectRefused(*elsewhere, "regular", "scene 'checkpoint_test'");
  auto fresh = makeSim(tank("pbf"), sph::Method::Regular);
  expectRefused(*fresh, "surface", "method 'regular'");
}

TEST_F(CheckpointRefusal, SceneOfOtherParticleMasses) {
  sph::Scene heavier = tank("pbf");
  heavier.params.mass_small *= 2.0;
  heavier.params.mass_large *= 2.0;
  heavier.large_particles /= 2;
  auto other = makeSim(heavier, sph::Method::Regular);
  expectRefused(*other, "regular", "another mass or support than its level has here");
}

TEST_F(CheckpointRefusal, TruncatedCorruptedOrForeignFile) {
  auto fresh = makeSim(tank("pbf"), sph::Method::Regular);
  write(bytes_.substr(0, bytes_.size() / 2));
  expectRefused(*fresh, "regular", "checksum");
  std::string flipped = bytes_;
  flipped[flipped.size() / 2] ^= 0x40;
  write(flipped);
  expectRefused(*fresh, "regular", "checksum");
  write("{\"not\": \"a checkpoint\"}");
  expectRefused(*fresh, "regular", "not a checkpoint");
  std::filesystem::remove(path_);
  expectRefused(*fresh, "regular", "cannot open");
}

}  // namespace
