// ParticleSet storage: permute and compact move every attribute together; the capacity is a hard
// ceiling; mass and class counts; every attribute declared once, with the split and merge rules applied.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "sph/particles.h"

namespace {

using sph::Level;
using sph::Vec3;

// n particles, alternating classes, every attribute set to a value derived from the particle's id.
sph::ParticleSet makeSet(std::size_t n, std::size_t capacity) {
  const auto classes = sph::thesisPreset().levelProps();
  sph::ParticleSet p(capacity);
  for (std::size_t i = 0; i < n; ++i) {
    const Level c = (i % 3 == 0) ? Level{1} : Level{0};
    const float f = static_cast<float>(i);
    p.add(Vec3(f, 2.0f * f, 3.0f * f), Vec3(-f, 0.5f * f, 7.0f), c, classes[sph::levelIndex(c)]);
    p.acceleration.back() = Vec3(f + 0.25f, f, -f);
    p.density.back() = 1000.0f + f;
    p.pressure.back() = 10.0f * f;
    p.normal_length.back() = 0.125f * f;
    p.pressure_term.back() = 0.5f * f;
    p.volume.back() = 2.0f + f;
  }
  return p;
}

// Every attribute of particle k matches the values makeSet gave the particle with id `id`.
void expectParticleIs(const sph::ParticleSet& p, std::size_t k, std::uint32_t id) {
  const auto classes = sph::thesisPreset().levelProps();
  const float f = static_cast<float>(id);
  const Level c = (id % 3 == 0) ? Level{1} : Level{0};
  SCOPED_TRACE(::testing::Message() << "index " << k << ", id " << id);
  EXPECT_EQ(p.id[k], id);
  EXPECT_EQ(p.level[k], c);
  EXPECT_EQ(p.mass[k], static_cast<float>(classes[sph::levelIndex(c)].mass));
  EXPECT_EQ(p.radius[k], static_cast<float>(classes[sph::levelIndex(c)].radius));
  EXPECT_EQ(p.support[k], static_cast<float>(classes[sph::levelIndex(c)].support));
  EXPECT_EQ(p.position[k], Vec3(f, 2.0f * f, 3.0f * f));
  EXPECT_EQ(p.velocity[k], Vec3(-f, 0.5f * f, 7.0f));
  EXPECT_EQ(p.acceleration[k], Vec3(f + 0.25f, f, -f));
  EXPECT_EQ(p.density[k], 1000.0f + f);
  EXPECT_EQ(p.pressure[k], 10.0f * f);
  EXPECT_EQ(p.normal_length[k], 0.125f * f);
  EXPECT_EQ(p.pressure_term[k], 0.5f * f);
  EXPECT_EQ(p.volume[k], 2.0f + f);
}

TEST(ParticleSet, AddAssignsSequentialIds) {
  const sph::ParticleSet p = makeSet(10, 16);
  ASSERT_EQ(p.size(), 10u);
  for (std::size_t k = 0; k < p.size(); ++k) expectParticleIs(p, k, static_cast<std::uint32_t>(k));
}

TEST(ParticleSet, PermuteMovesEveryAttribute) {
  sph::ParticleSet p = makeSet(7, 16);
  const std::vector<std::uint32_t> order = {4, 0, 6, 2, 1, 5, 3};
  p.permute(order);
  ASSERT_EQ(p.size(), 7u);
  for (std::size_t k = 0; k < order.size(); ++k) expectParticleIs(p, k, order[k]);
  EXPECT_EQ(p.capacity(), 16u);

  const std::vector<std::uint32_t> wrong_size = {0, 1};
  EXPECT_THROW(p.permute(wrong_size), std::invalid_argument);
}

TEST(ParticleSet, CompactKeepsFlaggedInOrder) {
  sph::ParticleSet p = makeSet(8, 16);
  const std::vector<std::uint8_t> keep = {1, 0, 0, 1, 1, 0, 1, 0};
  EXPECT_EQ(p.compact(keep), 4u);
  ASSERT_EQ(p.size(), 4u);
  const std::uint32_t kept[] = {0, 3, 4, 6};
  for (std::size_t k = 0; k < 4; ++k) expectParticleIs(p, k, kept[k]);
  p.forEachAttribute([&](const auto& v) { EXPECT_EQ(v.size(), 4u); });

  // New particles after a compaction get fresh ids, never reused ones.
  const auto classes = sph::thesisPreset().levelProps();
  EXPECT_EQ(p.add(Vec3::Zero(), Vec3::Zero(), Level{0}, classes[0]), 8u);
}

TEST(ParticleSet, AddPastCapacityThrows) {
  sph::ParticleSet p = makeSet(5, 5);
  const auto classes = sph::thesisPreset().levelProps();
  EXPECT_THROW(p.add(Vec3::Zero(), Vec3::Zero(), Level{0}, classes[0]), std::length_error);
  EXPECT_EQ(p.size(), 5u);
  p.forEachAttribute([&](const auto& v) { EXPECT_EQ(v.size(), 5u); });
}

TEST(ParticleSet, TotalMassAndClassCounts) {
  const sph::ParticleSet p = makeSet(10, 16);  // ids 0, 3, 6, 9 L1
  const auto classes = sph::thesisPreset().levelProps();
  EXPECT_EQ(p.countOf(Level{1}), 4u);
  EXPECT_EQ(p.countOf(Level{0}), 6u);
  const double expected = 4.0 * static_cast<float>(classes[1].mass) + 6.0 * static_cast<float>(classes[0].mass);
  EXPECT_DOUBLE_EQ(p.totalMass(), expected);
  EXPECT_NEAR(p.totalMass(), 4 * 0.02 + 6 * 0.01, 1e-8);

  sph::ParticleSet empty(4);
  EXPECT_TRUE(empty.empty());
  EXPECT_EQ(empty.totalMass(), 0.0);
  EXPECT_EQ(empty.countOf(Level{0}), 0u);
}

}  // namespace

TEST(ParticleSet, SwapRemoveMovesTheLastParticlesIntoTheHoles) {
  sph::ParticleSet p = makeSet(8, 16);
  const std::vector<std::uint8_t> keep = {1, 0, 1, 1, 0, 1, 1, 0};  // remove 1, 4, 7
  p.swapRemove(keep);
  ASSERT_EQ(p.size(), 5u);
  // From the highest index down: 7 is the last (just dropped), 6 fills 4, 5 fills 1.
  const std::uint32_t expected[] = {0, 5, 2, 3, 6};
  for (std::size_t k = 0; k < p.size(); ++k) expectParticleIs(p, k, expected[k]);
  EXPECT_THROW(p.swapRemove(std::vector<std::uint8_t>(9, 1)), std::invalid_argument);

  // A moved particle moves again: 4 fills 3, then (now last) fills 1.
  sph::ParticleSet q = makeSet(5, 16);
  q.swapRemove(std::vector<std::uint8_t>{1, 0, 1, 0, 1});
  ASSERT_EQ(q.size(), 3u);
  const std::uint32_t chained[] = {0, 4, 2};
  for (std::size_t k = 0; k < q.size(); ++k) expectParticleIs(q, k, chained[k]);
}

TEST(ParticleSet, AppendResetGivesFreshIdsAndResetValues) {
  sph::ParticleSet p = makeSet(3, 8);
  const std::size_t first = p.appendReset(2);
  ASSERT_EQ(first, 3u);
  ASSERT_EQ(p.size(), 5u);
  EXPECT_EQ(p.id[3], 3u);
  EXPECT_EQ(p.id[4], 4u);
  EXPECT_EQ(p.position[4], Vec3::Zero());
  EXPECT_EQ(p.velocity[3], Vec3::Zero());
  EXPECT_EQ(p.mass[4], 0.0f);
  EXPECT_EQ(p.surface_distance[4], std::numeric_limits<float>::infinity());
  EXPECT_THROW(p.appendReset(4), std::length_error);
}

// Each attribute is listed once in kParticleAttributes (the static_assert there catches a missing
// one only by count; this catches one listed twice in place of another), by a unique name.
TEST(ParticleAttributes, EveryAttributeIsDeclaredOnceWithAName) {
  sph::ParticleSet p(4);
  std::set<const void*> vectors;
  std::set<std::string> names;
  std::size_t count = 0;
  p.forEachAttributeSpec([&](auto& v, const auto& spec) {
    ++count;
    vectors.insert(&v);
    ASSERT_NE(spec.name, nullptr);
    names.insert(spec.name);
  });
  EXPECT_EQ(vectors.size(), count);
  EXPECT_EQ(names.size(), count);
  EXPECT_EQ(count * sizeof(std::vector<float>), sizeof(sph::ParticleAttributes));
}

// The class-derived attributes are exactly the ones setLevel sets.
TEST(ParticleAttributes, LevelRulesAreTheAttributesSetLevelSets) {
  sph::ParticleSet p(4);
  std::set<std::string> split_class, merge_class;
  p.forEachAttributeSpec([&](auto&, const auto& spec) {
    if (spec.split == sph::SplitRule::kLevel) split_class.insert(spec.name);
    if (spec.merge == sph::MergeRule::kLevel) merge_class.insert(spec.name);
  });
  const std::set<std::string> expected = {"level", "radius", "support"};
  EXPECT_EQ(split_class, expected);
  EXPECT_EQ(merge_class, expected);
}

// Split and merge apply each attribute's rule: a parent whose every attribute holds a distinct
// value, split, then its two children merged again.
TEST(ParticleAttributes, SplitAndMergeApplyEachRule) {
  const auto classes = sph::thesisPreset().levelProps();
  const auto& small = classes[sph::levelIndex(Level{0})];
  const auto& large = classes[sph::levelIndex(Level{1})];
  sph::ParticleSet p = makeSet(1, 4);  // id 0: L1
  p.surface_distance[0] = 0.5f;
  p.surface_hop[0] = 0.25f;
  const sph::ParticleSet before = p;
  const std::size_t c = p.appendReset(1);
  p.splitInto(0, c, Level{0}, small);

  sph::ParticleSet& q = p;
  q.forEachAttributeSpec([&](auto& v, const auto& spec) {
    SCOPED_TRACE(spec.name);
    const auto& parent = before.*spec.member;
    switch (spec.split) {
      case sph::SplitRule::kCopy:
        EXPECT_EQ(v[0], parent[0]);
        EXPECT_EQ(v[c], parent[0]);
        break;
      case sph::SplitRule::kHalve:
        if constexpr (std::is_arithmetic_v<std::decay_t<decltype(v[0])>>) {
          EXPECT_EQ(v[0], 0.5f * parent[0]);
          EXPECT_EQ(v[c], 0.5f * parent[0]);
        }
        break;
      case sph::SplitRule::kReset:
        EXPECT_EQ(v[0], spec.reset_value);
        EXPECT_EQ(v[c], spec.reset_value);
        break;
      case sph::SplitRule::kMark:
        if constexpr (std::is_arithmetic_v<std::decay_t<decltype(v[0])>>) {
          EXPECT_EQ(parent[0], 0);  // a fresh set: nothing placed yet
          EXPECT_EQ(v[0], 1);
          EXPECT_EQ(v[c], 1);
        }
        break;
      case sph::SplitRule::kFreshId:
        EXPECT_EQ(v[0], parent[0]);
        EXPECT_NE(v[c], parent[0]);
        break;
      case sph::SplitRule::kLevel:
        break;  // below
    }
  });
  for (std::size_t k : {std::size_t{0}, c}) {
    EXPECT_EQ(p.level[k], Level{0});
    EXPECT_EQ(p.mass[k], static_cast<float>(small.mass));  // halving the L1 mass is exact
    EXPECT_EQ(p.radius[k], static_cast<float>(small.radius));
    EXPECT_EQ(p.support[k], static_cast<float>(small.support));
  }

  // Make the two children differ, then merge them.
  p.position[c] += Vec3(0.25f, 0.0f, 0.0f);
  p.velocity[c] = Vec3(1.0f, 2.0f, 3.0f);
  p.density[c] = 2000.0f;
  p.normal_length[c] = 99.0f;
  p.surface_distance[c] = 0.125f;
  const sph::ParticleSet children = p;
  p.mergeInto(0, c, Level{1}, large);
  p.forEachAttributeSpec([&](auto& v, const auto& spec) {
    SCOPED_TRACE(spec.name);
    const auto& a = (children.*spec.member)[0];
    const auto& b = (children.*spec.member)[c];
    using T = std::decay_t<decltype(a)>;
    switch (spec.merge) {
      case sph::MergeRule::kKeep:
        EXPECT_EQ(v[0], a);
        break;
      case sph::MergeRule::kAverage:
        if constexpr (!std::is_enum_v<T>) {
          EXPECT_EQ(v[0], T(0.5f * (a + b)));
        }
        break;
      case sph::MergeRule::kSum:
        if constexpr (!std::is_enum_v<T>) {
          EXPECT_EQ(v[0], T(a + b));
        }
        break;
      case sph::MergeRule::kMin:
        if constexpr (std::is_arithmetic_v<T>) {
          EXPECT_EQ(v[0], std::min(a, b));
        }
        break;
      case sph::MergeRule::kMax:
        if constexpr (std::is_arithmetic_v<T>) {
          EXPECT_EQ(v[0], std::max(a, b));
        }
        break;
      case sph::MergeRule::kReset:
        EXPECT_EQ(v[0], spec.reset_value);
        break;
      case sph::MergeRule::kMark:
        if constexpr (std::is_arithmetic_v<T>) {
          EXPECT_EQ(v[0], 1);
        }
        break;
      case sph::MergeRule::kLevel:
        break;
    }
  });
  EXPECT_EQ(p.level[0], Level{1});
  EXPECT_EQ(p.mass[0], static_cast<float>(large.mass));
  EXPECT_EQ(p.radius[0], static_cast<float>(large.radius));
  EXPECT_EQ(p.normal_length[0], 99.0f);
  EXPECT_EQ(p.surface_distance[0], 0.125f);
}
