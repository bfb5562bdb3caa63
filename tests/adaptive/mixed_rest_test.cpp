// Water of both size classes at rest: L0 water over L1 water must stay where it is. The two
// classes have the same rest density, so a class that sinks through the other is a force that
// weighs them differently (pair_kernel.inc: the mixed pairs' kernel), not physics.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "adaptive_test_util.h"
#include "sph/adaptive/decide.h"
#include "sph/adaptive/split_merge.h"

namespace {

using adaptive_test::poolScene;

struct Layering {
  int l0_sunk = 0;   // L0 particles more than an L0 spacing below the interface
  int l1_risen = 0;  // L1 particles more than an L0 spacing above it
  int l0_count = 0;
  int l1_count = 0;
  double rms_speed = 0.0;
};

// An L1 pool at rest whose upper half is then split into L0 water, run `frames` more.
Layering l0OverL1(const char* preset, int frames) {
  sph::Scene scene = poolScene(0.3, 0.3, 1500);
  EXPECT_TRUE(sph::presetByName(preset, scene.params));
  scene.boundary.box.max.y() = 0.6;
  sph::Simulation sim(scene, sph::Level{1});
  for (int s = 0; s < 150; ++s) sim.step();
  float top = 0.0f;
  for (const sph::Vec3& x : sim.particles().position) top = std::max(top, x.y());
  const float interface_y = 0.5f * top;
  const std::size_t n = sim.particles().size();
  std::vector<std::int8_t> decision(n, sph::kRemain);
  for (std::size_t i = 0; i < n; ++i) {
    if (sim.particles().position[i].y() > interface_y) decision[i] = sph::kSplit;
  }
  std::vector<std::uint8_t> keep;
  std::vector<std::uint32_t> slots;
  sph::applySplitMerge(sim, decision, std::vector<std::int32_t>(n, -1), keep, slots);
  for (int s = 0; s < frames; ++s) sim.step();

  const sph::ParticleSet& p = sim.particles();
  const auto margin = static_cast<float>(std::cbrt(sim.params().mass_small / sim.params().rest_density));
  Layering out;
  double v2 = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    v2 += p.velocity[i].squaredNorm();
    if (p.level[i] == sph::Level{0}) {
      ++out.l0_count;
      out.l0_sunk += p.position[i].y() < interface_y - margin;
    } else {
      ++out.l1_count;
      out.l1_risen += p.position[i].y() > interface_y + margin;
    }
  }
  out.rms_speed = std::sqrt(v2 / static_cast<double>(p.size()));
  std::printf("%s, %d frames after the split: %d of %d L0 sunk, %d of %d L1 risen, rms %.4f m/s\n", preset, frames,
              out.l0_sunk, out.l0_count, out.l1_risen, out.l1_count, out.rms_speed);
  return out;
}

void expectLayersStay(const char* preset) {
  const Layering l = l0OverL1(preset, 300);
  // With the thesis's averaged kernel (3.35) L0 particles sank through the L1 ones and the
  // pool turned over slowly, with both presets. With the mean support's kernel (pair_kernels.h)
  // only a few particles cross and the pool stays near rest, in either instruction set; the bounds
  // below tell the two apart.
  EXPECT_LE(l.l0_sunk, l.l0_count / 50);
  EXPECT_LE(l.l1_risen, l.l1_count / 50);
  EXPECT_LT(l.rms_speed, 0.015);
}

TEST(MixedClasses, FinerWaterOverCoarserWaterStaysPbf) { expectLayersStay("pbf"); }
TEST(MixedClasses, FinerWaterOverCoarserWaterStaysDfsph) { expectLayersStay("dfsph"); }

}  // namespace
