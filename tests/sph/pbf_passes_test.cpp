// pbf's correction pass reads the kernel gradient factors its lambda pass kept at the same
// positions (PbfArrays::pair_g) instead of evaluating the kernel again: it must move every
// particle exactly as the evaluating form does, in each instruction set, for pairs of one class
// and mixed ones.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "sph/neighbor_grid.h"
#include "sph/params.h"
#include "sph/simd/simd_level.h"
#include "sph/solvers/incompressible_setup.h"
#include "sph/solvers/local_placement.h"
#include "sph/solvers/pbf/pbf_passes.h"

namespace {

// A compressed block of pbf water in a 0.6 m box: L0 particles in its left half, L1 ones in
// its right, each on its class's lattice squeezed to 0.9 of its spacing and jittered, so that the
// constraint pushes everywhere and the middle holds mixed pairs.
struct Block {
  sph::Scene scene;
  sph::IncompressibleSetup setup;
  sph::ParticleSet particles{8000};
  sph::NeighborGrid grid;

  Block() {
    EXPECT_TRUE(sph::presetByName("pbf", scene.params));
    scene.boundary.box.max = Eigen::Vector3d(0.6, 0.3, 0.3);
    setup = sph::makeIncompressibleSetup(scene);
    const auto classes = scene.params.levelProps();
    std::mt19937 rng(99);
    std::uniform_real_distribution<float> jitter(-0.05f, 0.05f);
    for (const sph::Level c : {sph::Level{0}, sph::Level{1}}) {
      const std::size_t k = sph::levelIndex(c);
      const float step = 0.9f * setup.spacing[k];
      const float x0 = c == sph::Level{0} ? 0.02f : 0.3f;
      for (float x = x0; x < x0 + 0.28f; x += step) {
        for (float y = 0.02f; y < 0.2f; y += step) {
          for (float z = 0.02f; z < 0.28f; z += step) {
            if (particles.size() == particles.capacity()) return;
            const sph::Vec3 at(x + jitter(rng) * step, y + jitter(rng) * step, z + jitter(rng) * step);
            particles.add(at, sph::Vec3::Zero(), c, classes[k]);
          }
        }
      }
    }
  }

  // Positions after one lambda pass and one correction pass of `forms`, keeping the pairs' g or not.
  std::vector<sph::Vec3> corrected(const sph::PbfPassForms& forms, bool keep) {
    sph::Aabb bounds;
    bounds.max = scene.boundary.box.max;
    grid.configure(bounds, std::max(setup.kernels[0].h, setup.kernels[1].h), particles.size());
    grid.build(particles);
    sph::PbfConstants c = sph::pbfConstantsOf(scene.params, setup);
    c.box = scene.boundary.stateAt(0.0);
    c.obstacles = &scene.boundary;
    const std::size_t n = particles.size();
    std::vector<float> lambda(n, 0.0f), lambda_step(n, 0.0f), pair_g(grid.slotCount());
    std::vector<sph::Vec3> wall_grad(n), next(n);
    sph::PbfArrays a = sph::pbfArraysOf(particles, lambda, lambda_step, wall_grad);
    a.position = particles.position.data()->data();
    a.position_next = next.data()->data();
    a.pair_g = keep ? pair_g.data() : nullptr;
    forms.lambda(a, c, grid);
    forms.correct(a, c, grid, false);
    return next;
  }
};

void expectKeptEqualsEvaluated(const sph::PbfPassForms& forms) {
  Block block;
  std::size_t mixed = 0;
  const auto one = block.corrected(forms, false);
  for (std::size_t i = 0; i < block.particles.size(); ++i) mixed += block.grid.hasOtherSupport(i) ? 1 : 0;
  ASSERT_GT(mixed, 100u) << "the block should hold mixed neighbourhoods";
  ASSERT_LT(mixed, block.particles.size() / 2) << "and neighbourhoods of one class";
  const auto kept = block.corrected(forms, true);
  std::size_t moved = 0;
  for (std::size_t i = 0; i < one.size(); ++i) {
    ASSERT_EQ(kept[i], one[i]) << "particle " << i;
    if (one[i] != block.particles.position[i]) ++moved;
  }
  EXPECT_GT(moved, one.size() * 9 / 10) << "the compressed block should move nearly every particle";
}

TEST(PbfPasses, CorrectionFromKeptGradientsEqualsTheEvaluatedOneScalar) {
  expectKeptEqualsEvaluated(sph::scalar::pbfPassForms());
}

TEST(PbfPasses, CorrectionFromKeptGradientsEqualsTheEvaluatedOneAvx2) {
  if (!sph::simdAvailable(sph::SimdLevel::kAvx2)) GTEST_SKIP() << "no AVX2 here";
  expectKeptEqualsEvaluated(sph::avx2::pbfPassForms());
}

TEST(PbfPasses, CorrectionFromKeptGradientsEqualsTheEvaluatedOneAvx512) {
  if (!sph::simdAvailable(sph::SimdLevel::kAvx512)) GTEST_SKIP() << "no AVX-512 here";
  expectKeptEqualsEvaluated(sph::avx512::pbfPassForms());
}

}  // namespace
