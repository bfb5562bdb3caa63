// Split (3.37)-(3.39) and merge (3.40)-(3.43) on their own: mass, momentum, placement, pairing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

#include "adaptive_test_util.h"
#include "sph/adaptive/decide.h"
#include "sph/adaptive/split_merge.h"
#include "sph/simd/simd_level.h"
#include "sph/solvers/thesis/thesis_stages.h"

namespace {

using adaptive_test::momentum;
using adaptive_test::poolScene;

// Runs one step so that neighbour lists, densities and normals exist, then gives every particle
// some velocity so momentum is not trivially zero.
void prepare(sph::Simulation& sim) {
  sim.step();
  sph::ParticleSet& p = sim.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.velocity[i] = sph::Vec3(0.1f * std::sin(0.37f * i), 0.2f * std::cos(0.11f * i), 0.05f);
  }
}

TEST(SplitMerge, SplitKeepsMassMomentumAndCentreOfMass) {
  sph::Simulation sim(poolScene(0.4, 0.4, 600), sph::Level{1});
  prepare(sim);
  sph::ParticleSet& p = sim.particles();
  const std::size_t n = p.size();
  const double mass_before = p.totalMass();
  const Eigen::Vector3d momentum_before = momentum(p);
  Eigen::Vector3d centre_before = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < n; ++i) centre_before += p.mass[i] * p.position[i].cast<double>();

  std::vector<std::int8_t> decision(n, sph::kSplit);
  std::vector<std::int32_t> partner(n, -1);
  std::vector<std::uint8_t> keep;
  std::vector<std::uint32_t> slots;
  const auto counts = sph::applySplitMerge(sim, decision, partner, keep, slots);

  EXPECT_EQ(counts.splits, static_cast<int>(n));
  EXPECT_EQ(counts.merges, 0);
  ASSERT_EQ(p.size(), 2 * n);
  EXPECT_EQ(p.countOf(sph::Level{0}), 2 * n);
  EXPECT_EQ(p.totalMass(), mass_before);
  EXPECT_LT((momentum(p) - momentum_before).norm(), 1e-9 * (1.0 + momentum_before.norm()));
  Eigen::Vector3d centre_after = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < p.size(); ++i) centre_after += p.mass[i] * p.position[i].cast<double>();
  // Children are symmetric about the parent except where an obstacle pushed one: none here.
  EXPECT_LT((centre_after - centre_before).norm() / mass_before, 1e-6);

  std::set<std::uint32_t> ids(p.id.begin(), p.id.end());
  EXPECT_EQ(ids.size(), p.size()) << "ids must stay unique";
  const sph::BoxState box = sim.boxNow();
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      EXPECT_GE(p.position[i][a], box.min[a] + p.radius[i] - 1e-6f);
      EXPECT_LE(p.position[i][a], box.max[a] - p.radius[i] + 1e-6f);
    }
  }
  // The two children of parent i (slot i and slot n + i) never share a point.
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_GT((p.position[i] - p.position[n + i]).norm(), 1e-4f);
  }
}

// In a box corner the walls cut every axis short; the children of the incompressible solvers'
// roomiest axis still land a parent radius apart (one at the parent's centre, one towards the
// box's inside), never on one point, and inside the box.
TEST(SplitMerge, InABoxCornerTheChildrenLandAParentRadiusApart) {
  sph::Scene scene = poolScene(0.3, 0.3, 1500);
  ASSERT_TRUE(sph::presetByName("pbf", scene.params));
  scene.boundary.box.max.y() = 0.6;
  sph::Simulation sim(scene, sph::Level{1});
  for (int s = 0; s < 5; ++s) sim.step();
  sph::ParticleSet& p = sim.particles();
  const sph::BoxState box = sim.boxNow();
  std::size_t corner = 0;
  for (std::size_t i = 1; i < p.size(); ++i) {
    if ((p.position[i] - box.min).norm() < (p.position[corner] - box.min).norm()) corner = i;
  }
  for (int a = 0; a < 3; ++a) ASSERT_LT(p.position[corner][a] - box.min[a], p.radius[corner]) << "axis " << a;
  const float parent_radius = p.radius[corner];
  const double mass_before = p.totalMass();
  std::vector<std::int8_t> decision(p.size(), sph::kRemain);
  decision[corner] = sph::kSplit;
  std::vector<std::uint8_t> keep;
  std::vector<std::uint32_t> slots;
  const auto counts = sph::applySplitMerge(sim, decision, std::vector<std::int32_t>(p.size(), -1), keep, slots);
  ASSERT_EQ(counts.splits, 1);
  const sph::Vec3 a = p.position[corner];
  const sph::Vec3 b = p.position[p.size() - 1];
  EXPECT_GT((a - b).norm(), 0.9f * parent_radius);
  EXPECT_EQ(p.totalMass(), mass_before);
  for (const std::size_t i : {corner, p.size() - 1}) {
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_GE(p.position[i][axis], box.min[axis] + p.radius[i] - 1e-6f);
      EXPECT_LE(p.position[i][axis], box.max[axis] - p.radius[i] + 1e-6f);
    }
  }
}

TEST(SplitMerge, MergeKeepsMassAndMomentumAndPairsEachParticleOnce) {
  sph::Simulation sim(poolScene(0.4, 0.4, 500), sph::Level{0});
  prepare(sim);
  sph::ParticleSet& p = sim.particles();
  const std::size_t n = p.size();
  const double mass_before = p.totalMass();
  const Eigen::Vector3d momentum_before = momentum(p);

  std::vector<std::int8_t> decision(n, sph::kMerge);
  std::vector<std::int32_t> partner(n, -1);
  sph::PartnerScratch partner_scratch;
  sph::choosePartners(p, sim.grid(), decision, partner, sph::Level{1}, partner_scratch);
  // Every particle is in at most one mutual pair.
  std::vector<int> pair_count(n, 0);
  int pairs = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t j = partner[i];
    if (j >= 0 && partner[static_cast<std::size_t>(j)] == static_cast<std::int32_t>(i) &&
        static_cast<std::size_t>(j) > i) {
      ++pair_count[i];
      ++pair_count[static_cast<std::size_t>(j)];
      ++pairs;
    }
  }
  for (std::size_t i = 0; i < n; ++i) ASSERT_LE(pair_count[i], 1) << "particle " << i;
  ASSERT_GT(pairs, static_cast<int>(n / 4)) << "mutual nearest pairs should cover much of a lattice";

  std::vector<std::uint8_t> keep;
  std::vector<std::uint32_t> slots;
  const auto counts = sph::applySplitMerge(sim, decision, partner, keep, slots);
  EXPECT_EQ(counts.merges, pairs);
  EXPECT_EQ(p.size(), n - static_cast<std::size_t>(pairs));
  EXPECT_EQ(p.countOf(sph::Level{1}), static_cast<std::size_t>(pairs));
  EXPECT_EQ(p.totalMass(), mass_before);
  EXPECT_LT((momentum(p) - momentum_before).norm(), 1e-6 * (1.0 + momentum_before.norm()));
}

TEST(SplitMerge, LargeParticlesAreNeverMergedAndSmallNeverSplit) {
  sph::Simulation sim(poolScene(0.3, 0.3, 300), sph::Level{1});
  prepare(sim);
  sph::ParticleSet& p = sim.particles();
  const std::size_t n = p.size();
  std::vector<std::int8_t> merge_all(n, sph::kMerge);
  std::vector<std::int32_t> partner(n, 0);
  sph::PartnerScratch partner_scratch;
  sph::choosePartners(p, sim.grid(), merge_all, partner, sph::Level{1}, partner_scratch);
  for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(partner[i], -1);

  std::vector<std::int8_t> split_all(n, sph::kSplit);
  std::vector<std::uint8_t> keep;
  std::vector<std::uint32_t> slots;
  sph::applySplitMerge(sim, split_all, std::vector<std::int32_t>(n, -1), keep, slots);
  ASSERT_EQ(p.size(), 2 * n);
  std::vector<std::int8_t> split_again(p.size(), sph::kSplit);
  const auto counts = sph::applySplitMerge(sim, split_again, std::vector<std::int32_t>(p.size(), -1), keep, slots);
  EXPECT_EQ(counts.splits, 0);
  EXPECT_EQ(p.size(), 2 * n);
}

// Splitting every particle of a fluid at rest changes its mean density by less than 5 %.
TEST(SplitMerge, SplittingARestingFluidKeepsItsMeanDensity) {
  sph::Simulation sim(poolScene(0.5, 0.5, 1500), sph::Level{1});
  sim.rebuildNeighbors();
  sph::computeDensityPressure(sim.params(), sph::makeKernelTable(sim.params()), sim.grid(), sim.particles());
  auto meanDensity = [&] {
    double sum = 0.0;
    for (float rho : sim.particles().density) sum += rho;
    return sum / static_cast<double>(sim.particles().size());
  };
  const double before = meanDensity();
  const std::size_t n = sim.particles().size();
  std::vector<std::uint8_t> keep;
  std::vector<std::uint32_t> slots;
  sph::applySplitMerge(sim, std::vector<std::int8_t>(n, sph::kSplit), std::vector<std::int32_t>(n, -1), keep, slots);
  sim.rebuildNeighbors();
  sph::computeDensityPressure(sim.params(), sph::makeKernelTable(sim.params()), sim.grid(), sim.particles());
  const double after = meanDensity();
  EXPECT_LT(std::abs(after - before) / before, 0.05) << "before " << before << " after " << after;
}

// How much a split or merge step may add, to the rms speed (m/s) and to the largest density error
// (a share of rho0), with the frames the pool rests first, and the largest rms (m/s) in the 50
// frames after.
struct PlacementBounds {
  int settle_frames;
  double kick;
  float compression;
  double peak;
};

// Splitting every particle of a resting pool, then merging every pair it can: where the split or
// merge puts the particles is the method's choice, not a motion of the water (local_placement.h,
// `placed`), so the pool must not be thrown, nor compressed beyond the bounds.
void expectSplittingOrMergingARestingPoolDoesNotKickIt(const char* preset, const PlacementBounds& bounds) {
  sph::Scene scene = poolScene(0.3, 0.3, 1500);
  ASSERT_TRUE(sph::presetByName(preset, scene.params));
  scene.boundary.box.max.y() = 0.6;
  sph::Simulation sim(scene, sph::Level{1});
  const double initial_mass = sim.particles().totalMass();
  auto rms = [&] {
    double v2 = 0.0;
    for (const sph::Vec3& v : sim.particles().velocity) v2 += v.squaredNorm();
    return std::sqrt(v2 / static_cast<double>(sim.particles().size()));
  };
  // As the density constraint sees it: pbf holds a change in still water at the density the
  // change gave it, the offset fading over a third of a second (still_water_changes.h).
  auto maxCompression = [&] {
    const sph::ParticleSet& p = sim.particles();
    float most = 0.0f;
    for (std::size_t i = 0; i < p.size(); ++i) {
      most = std::max(most, (p.density[i] - p.density_offset[i]) / static_cast<float>(sim.params().rest_density));
    }
    return most - 1.0f;
  };
  // The 50 frames after a split or merge: the pool near rest again at their end, mass exact by
  // class, and in between below bounds.peak. The pool breathes after a whole split or merge
  // (docs/fluids.md, the split's lift), its rms peaking a few frames on: the bound makes a worse
  // placement show.
  const auto expectSettlesAgain = [&] {
    double peak = 0.0;
    for (int s = 0; s < 50; ++s) {
      sim.step();
      peak = std::max(peak, rms());
    }
    std::printf("rms 50 frames later %.4f m/s (at most %.4f in between)\n", rms(), peak);
    EXPECT_LT(rms(), 0.15);
    EXPECT_LT(peak, bounds.peak);
    adaptive_test::expectMassByClass(sim, initial_mass);
  };
  for (int s = 0; s < bounds.settle_frames; ++s) sim.step();
  EXPECT_EQ(sim.lastSolverStats().placement_iterations, 0);  // nothing placed since the start
  const double rest = rms();
  const float compression_before = maxCompression();

  const std::size_t n = sim.particles().size();
  std::vector<std::uint8_t> keep;
  std::vector<std::uint32_t> slots;
  sph::applySplitMerge(sim, std::vector<std::int8_t>(n, sph::kSplit), std::vector<std::int32_t>(n, -1), keep, slots);
  ASSERT_EQ(sim.particles().size(), 2 * n);
  sim.step();
  // The children's placement is counted apart from the solver's own iterations.
  EXPECT_GT(sim.lastSolverStats().placement_iterations, 0);
  const double after_split = rms();
  std::printf("rms %.4f -> %.4f m/s in the split step; max compression %.4f -> %.4f\n", rest, after_split,
              compression_before, maxCompression());
  EXPECT_LT(after_split, rest + bounds.kick);
  EXPECT_LE(maxCompression() - compression_before, bounds.compression);
  expectSettlesAgain();

  // Merging every pair it can back: likewise.
  const double before_merge = rms();
  const float compression_before_merge = maxCompression();
  const std::size_t m = sim.particles().size();
  std::vector<std::int8_t> merge_all(m, sph::kMerge);
  std::vector<std::int32_t> partner(m, -1);
  sph::PartnerScratch partner_scratch;
  sph::choosePartners(sim.particles(), sim.grid(), merge_all, partner, sph::Level{1}, partner_scratch);
  const auto counts = sph::applySplitMerge(sim, merge_all, partner, keep, slots);
  ASSERT_GT(counts.merges, static_cast<int>(m / 4));
  sim.step();
  const double after_merge = rms();
  std::printf("merged %d pairs: rms %.4f -> %.4f m/s; max compression %.4f -> %.4f\n", counts.merges, before_merge,
              after_merge, compression_before_merge, maxCompression());
  EXPECT_LT(after_merge, before_merge + bounds.kick);
  EXPECT_LE(maxCompression() - compression_before_merge, bounds.compression);
  expectSettlesAgain();
}

// pbf: the split raises the largest density error (as the constraint sees it: in still water it
// holds what the placement leaves, still_water_changes.h) by at most 5 %, because the placement
// moves the compressed children before the constraint (without it the error grows well past
// that), and adds little kick. Before the placement rule the split step threw the pool, which
// still moved 50 frames later; before the neighbours of a merge counted as placed the merge step
// threw it too. In the frames after a whole split or merge the pool breathes (both solvers, more
// than a pool without a split); the 0.2 m/s peak keeps it from growing.
TEST(SplitMerge, SplittingOrMergingARestingPbfPoolDoesNotKickIt) {
  expectSplittingOrMergingARestingPoolDoesNotKickIt("pbf", {6, 0.03, 0.05f, 0.2});
}

// dfsph, from rest after 150 frames: without the placement the split step threw the pool. With it
// the split raises the largest density error only a little (less than with the drawn directions
// used before the roomiest axis, split_axis.h; the pool rests slightly compressed since the solve
// holds the floor layer, floor_contact.h) but still sets the pool moving, and the merge adds to
// that: more than pbf's (docs/fluids.md), so the kick's bound here is 0.1 m/s. The frames after:
// as pbf's.
TEST(SplitMerge, SplittingOrMergingARestingDfsphPoolDoesNotThrowIt) {
  expectSplittingOrMergingARestingPoolDoesNotKickIt("dfsph", {150, 0.1, 0.05f, 0.2});
}

// The vector searches (8 or 16 neighbours at a time, each lane keeping its own best) must choose
// exactly as the scalar one: on the water's lattice as filled (many equal distances, so the id
// decides), then on a mixed set (L1 particles, which never pair, among the L0 ones); every
// fifth particle does not want to merge. Every vector form the CPU has.
void expectPartnerSearchChoosesAsTheScalarOne(decltype(&sph::scalar::choosePartners) vector_search) {
  sph::Simulation sim(poolScene(0.4, 0.4, 1200), sph::Level{0});
  sph::ParticleSet& p = sim.particles();
  for (int round = 0; round < 2; ++round) {
    sim.rebuildNeighbors();
    const std::size_t n = p.size();
    std::vector<std::int8_t> decision(n, sph::kMerge);
    for (std::size_t i = 0; i < n; i += 5) decision[i] = sph::kRemain;
    std::vector<std::int32_t> vector_choice(n, 7), scalar_choice(n, 7);
    sph::PartnerScratch scratch;
    vector_search(p, sim.grid(), decision, vector_choice, sph::Level{1}, scratch);
    sph::scalar::choosePartners(p, sim.grid(), decision, scalar_choice, sph::Level{1}, scratch);
    EXPECT_EQ(vector_choice, scalar_choice) << "round " << round;
    std::size_t paired = 0;
    for (std::int32_t c : scalar_choice) paired += c >= 0;
    EXPECT_GT(paired, n / 2) << "round " << round;
    // Merge the mutual pairs within the first third: round 2 searches a mixed set, L1
    // particles among the L0 ones.
    std::vector<std::uint8_t> keep;
    std::vector<std::uint32_t> slots;
    std::vector<std::int32_t> merge_some(scalar_choice);
    for (std::size_t i = n / 3; i < n; ++i) merge_some[i] = -1;
    sph::applySplitMerge(sim, decision, merge_some, keep, slots);
  }
  EXPECT_GT(p.countOf(sph::Level{1}), 0u);
}

TEST(SplitMerge, VectorPartnerSearchChoosesAsTheScalarOneAvx2) {
  if (!sph::simdAvailable(sph::SimdLevel::kAvx2)) GTEST_SKIP() << "no AVX2 here";
  expectPartnerSearchChoosesAsTheScalarOne(sph::avx2::choosePartners);
}

TEST(SplitMerge, VectorPartnerSearchChoosesAsTheScalarOneAvx512) {
  if (!sph::simdAvailable(sph::SimdLevel::kAvx512)) GTEST_SKIP() << "no AVX-512 here";
  expectPartnerSearchChoosesAsTheScalarOne(sph::avx512::choosePartners);
}

TEST(SplitMerge, SplitDirectionIsAUnitVectorThatDependsOnTheId) {
  for (std::uint32_t id : {0u, 1u, 2u, 12345u, 4000000000u}) {
    EXPECT_NEAR(sph::splitDirection(id).norm(), 1.0f, 1e-5f);
    EXPECT_EQ(sph::splitDirection(id), sph::splitDirection(id));
  }
  EXPECT_NE(sph::splitDirection(1), sph::splitDirection(2));
}

}  // namespace

namespace {

// An L0 particle that wants to merge but has no merging L0 neighbour within reach would stay
// L0 for good; stragglers pair among themselves within two L0 support radii.
TEST(SplitMerge, StragglersPairWithinTwoSupportRadiiOnly) {
  sph::Simulation sim(poolScene(0.4, 0.4, 500), sph::Level{0});
  prepare(sim);
  sph::ParticleSet& p = sim.particles();
  const std::size_t n = p.size();
  const float h = static_cast<float>(sim.params().levelProps()[0].support);
  const std::size_t a = 0;
  std::size_t b = n, c = n;
  for (std::size_t i = 1; i < n; ++i) {
    const float d = (p.position[i] - p.position[a]).norm();
    if (b == n && d > 1.2f * h && d < 1.8f * h) b = i;
  }
  ASSERT_LT(b, n);
  for (std::size_t i = 1; i < n; ++i) {
    if ((p.position[i] - p.position[a]).norm() > 4.0f * h && (p.position[i] - p.position[b]).norm() > 4.0f * h) {
      c = i;
      break;
    }
  }
  ASSERT_LT(c, n);
  std::vector<std::int8_t> decision(n, sph::kRemain);
  decision[a] = decision[b] = decision[c] = sph::kMerge;
  std::vector<std::int32_t> partner(n, 0);
  sph::PartnerScratch partner_scratch;
  sph::choosePartners(p, sim.grid(), decision, partner, sph::Level{1}, partner_scratch);
  ASSERT_EQ(partner[a], -1) << "no merging neighbour within reach";
  ASSERT_EQ(partner[b], -1);
  sph::StragglerScratch scratch;
  sph::pairStragglers(p, decision, partner, 2.0f, sph::Level{1}, scratch);
  EXPECT_EQ(partner[a], static_cast<std::int32_t>(b));
  EXPECT_EQ(partner[b], static_cast<std::int32_t>(a));
  EXPECT_EQ(partner[c], -1) << "too far from every other straggler";

  const double mass = p.totalMass();
  std::vector<std::uint8_t> keep;
  std::vector<std::uint32_t> slots;
  const auto counts = sph::applySplitMerge(sim, decision, partner, keep, slots);
  EXPECT_EQ(counts.merges, 1);
  EXPECT_EQ(p.countOf(sph::Level{1}), 1u);
  EXPECT_EQ(p.totalMass(), mass);
}

// The sweep along x must pair exactly as comparing every two stragglers would: mutual nearest
// within the distance, ties to the lower index. A lattice (many equal distances) with gaps.
TEST(SplitMerge, StragglerSweepPairsAsTheQuadraticSearch) {
  const auto classes = sph::thesisPreset().levelProps();
  const auto& small = classes[sph::levelIndex(sph::Level{0})];
  sph::ParticleSet p(400);
  const float spacing = 0.03f;
  for (int k = 0; k < 1000 && p.size() < 400; ++k) {
    if ((k * 7919) % 5 == 0) continue;  // gaps, so some stragglers lose their nearest
    const sph::Vec3 x(spacing * static_cast<float>(k % 10), spacing * static_cast<float>((k / 10) % 10),
                      spacing * static_cast<float>(k / 100));
    p.add(x, sph::Vec3::Zero(), sph::Level{0}, small);
  }
  const std::size_t n = p.size();
  // The reach is in support radii: 1.2 spacings.
  const float reach = 1.2f * spacing / p.support[0];
  const float max_distance = reach * p.support[0];
  std::vector<std::int8_t> decision(n, sph::kMerge);
  for (std::size_t i = 0; i < n; i += 9) decision[i] = sph::kRemain;

  // Reference: every pair, indices ascending.
  std::vector<std::uint32_t> lonely;
  for (std::size_t i = 0; i < n; ++i) {
    if (decision[i] == sph::kMerge) lonely.push_back(static_cast<std::uint32_t>(i));
  }
  std::vector<std::int32_t> nearest(lonely.size(), -1);
  for (std::size_t a = 0; a < lonely.size(); ++a) {
    float best = max_distance * max_distance;
    for (std::size_t b = 0; b < lonely.size(); ++b) {
      const float d2 = (p.position[lonely[a]] - p.position[lonely[b]]).squaredNorm();
      if (a != b && d2 < best) {
        best = d2;
        nearest[a] = static_cast<std::int32_t>(b);
      }
    }
  }
  std::vector<std::int32_t> expected(n, -1);
  int pairs = 0;
  for (std::size_t a = 0; a < lonely.size(); ++a) {
    const std::int32_t b = nearest[a];
    if (b >= 0 && nearest[static_cast<std::size_t>(b)] == static_cast<std::int32_t>(a)) {
      expected[lonely[a]] = static_cast<std::int32_t>(lonely[static_cast<std::size_t>(b)]);
      ++pairs;
    }
  }
  ASSERT_GT(pairs, 100) << "the lattice should pair most stragglers";

  std::vector<std::int32_t> partner(n, -1);
  sph::StragglerScratch scratch;
  sph::pairStragglers(p, decision, partner, reach, sph::Level{1}, scratch);
  EXPECT_EQ(partner, expected);
}

}  // namespace
