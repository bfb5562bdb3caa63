// The neighbour lists are packed back to back, one run per thread: whatever the thread count and
// however often the stride has to grow, each list holds exactly the pairs within (hi + hj) / 2
// (eq. (3.34)), in the same order; and the relation is symmetric.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "sph/neighbor_grid.h"
#include "sph/params.h"
#include "sph/particles.h"

namespace {

// `count` particles of both classes (L1 with probability `large_share`) at random in a cube of
// side `extent`, at rest.
sph::ParticleSet randomCloud(std::size_t count, float extent, double large_share, unsigned seed) {
  const auto classes = sph::thesisPreset().levelProps();
  sph::ParticleSet particles(count);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> pos(0.0f, extent);
  std::bernoulli_distribution large(large_share);
  while (particles.size() < particles.capacity()) {
    const sph::Level c = large(rng) ? sph::Level{1} : sph::Level{0};
    particles.add(sph::Vec3(pos(rng), pos(rng), pos(rng)), sph::Vec3::Zero(), c, classes[sph::levelIndex(c)]);
  }
  return particles;
}

// 3,000 particles in a 0.12 m cube: several times the rest density, so lists outgrow the
// starting stride of 96 and the grid must regrow it.
sph::ParticleSet denseCloud() { return randomCloud(3000, 0.12f, 0.3, 777); }

// 400 particles scattered in a 0.2 m cube (lists of a few to a few dozen).
sph::ParticleSet scatteredCloud() { return randomCloud(400, 0.2f, 0.5, 12345); }

// A grid over the cloud's cube, cells of the largest support radius.
sph::NeighborGrid cloudGrid(std::size_t capacity) {
  const auto classes = sph::thesisPreset().levelProps();
  sph::Aabb bounds;
  bounds.min = Eigen::Vector3d::Zero();
  bounds.max = Eigen::Vector3d::Constant(0.12);
  sph::NeighborGrid grid;
  grid.configure(bounds, static_cast<float>(std::max(classes[0].support, classes[1].support)), capacity);
  return grid;
}

// Runs f with OpenMP limited to `threads`, then restores the previous count.
template <typename F>
void withThreads(int threads, F&& f) {
  const int previous = omp_get_max_threads();
  omp_set_num_threads(threads);
  f();
  omp_set_num_threads(previous);
}

// The grid's lists of particles 0 .. count - 1, copied out.
std::vector<std::vector<std::uint32_t>> listsOf(const sph::NeighborGrid& grid, std::size_t count) {
  std::vector<std::vector<std::uint32_t>> lists(count);
  for (std::size_t i = 0; i < count; ++i) {
    const auto list = grid.neighbors(i);
    lists[i].assign(list.begin(), list.end());
  }
  return lists;
}

std::vector<std::vector<std::uint32_t>> listsWithThreads(const sph::ParticleSet& particles, int threads,
                                                         std::size_t* stride_growths) {
  sph::NeighborGrid grid = cloudGrid(particles.size());
  withThreads(threads, [&] { grid.build(particles); });
  *stride_growths = grid.strideGrowths();
  return listsOf(grid, particles.size());
}

// Every pair within reach, in any order: brute force against the grid's lists.
void expectExactLists(const sph::ParticleSet& p, const std::vector<std::vector<std::uint32_t>>& lists) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::vector<std::uint32_t> expected;
    for (std::size_t j = 0; j < p.size(); ++j) {
      const float reach = 0.5f * (p.support[i] + p.support[j]);
      if (j != i && (p.position[i] - p.position[j]).squaredNorm() <= reach * reach) {
        expected.push_back(static_cast<std::uint32_t>(j));
      }
    }
    std::vector<std::uint32_t> listed = lists[i];
    std::sort(listed.begin(), listed.end());
    ASSERT_EQ(listed, expected) << "particle " << i;
  }
}

TEST(NeighborGrid, PackedListsAreExactForAnyThreadCount) {
  const sph::ParticleSet p = denseCloud();
  std::size_t growths = 0;
  const auto one = listsWithThreads(p, 1, &growths);
  EXPECT_GE(growths, 1u) << "the cloud should be dense enough to outgrow the starting stride";
  expectExactLists(p, one);
  for (int threads : {2, 3}) {
    EXPECT_EQ(listsWithThreads(p, threads, &growths), one) << threads << " threads";
  }
}

// The counting sort is shared by the threads (each places its own share of the particles): the
// order must be the serial one whatever the thread count, ascending particle index inside a cell.
// Sorting particles already in cell order must then leave them where they are.
TEST(NeighborGrid, CellOrderIsTheSameForAnyThreadCount) {
  sph::ParticleSet p = denseCloud();
  const auto orderWith = [](const sph::ParticleSet& particles, int threads) {
    sph::NeighborGrid grid = cloudGrid(particles.size());
    withThreads(threads, [&] { grid.bin(particles); });
    return std::vector<std::uint32_t>(grid.cellOrder().begin(), grid.cellOrder().end());
  };
  const std::vector<std::uint32_t> one = orderWith(p, 1);
  std::vector<std::uint32_t> sorted = one;
  std::sort(sorted.begin(), sorted.end());
  for (std::uint32_t k = 0; k < sorted.size(); ++k) ASSERT_EQ(sorted[k], k) << "not a permutation";
  EXPECT_EQ(orderWith(p, 2), one);
  EXPECT_EQ(orderWith(p, 3), one);

  p.permute(one);
  std::vector<std::uint32_t> identity(p.size());
  for (std::uint32_t k = 0; k < identity.size(); ++k) identity[k] = k;
  for (int threads : {1, 2, 3}) EXPECT_EQ(orderWith(p, threads), identity) << threads << " threads";
}

// A NaN or infinite position (the step reports them; it must not corrupt the grid) lands in an
// inner cell: the other particles' lists stay exact and the broken ones have no neighbours.
TEST(NeighborGrid, NonFinitePositionsLeaveTheOtherListsExact) {
  sph::ParticleSet p = denseCloud();
  const float inf = std::numeric_limits<float>::infinity();
  p.position[10] = sph::Vec3(std::numeric_limits<float>::quiet_NaN(), 0.05f, 0.05f);
  p.position[20] = sph::Vec3(inf, inf, inf);
  p.position[30] = sph::Vec3(-inf, 0.05f, inf);
  std::size_t growths = 0;
  const auto lists = listsWithThreads(p, 2, &growths);
  expectExactLists(p, lists);
  for (std::size_t broken : {10u, 20u, 30u}) EXPECT_TRUE(lists[broken].empty()) << "particle " << broken;
}

// The simulation re-sorts the particles into cell order, so most particles share their cell's
// candidate rows with the ones before them: the lists must stay exact there too.
TEST(NeighborGrid, ListsAreExactForParticlesInCellOrder) {
  sph::ParticleSet p = denseCloud();
  sph::NeighborGrid grid = cloudGrid(p.size());
  grid.bin(p);
  const std::vector<std::uint32_t> order(grid.cellOrder().begin(), grid.cellOrder().end());
  p.permute(order);
  std::size_t growths = 0;
  const auto one = listsWithThreads(p, 1, &growths);
  expectExactLists(p, one);
  EXPECT_EQ(listsWithThreads(p, 2, &growths), one);
}

// Particles on the container's faces, edges and corners, in a box exactly three cells wide: a
// point on a far wall computes the index of the spare border cell, which the grid keeps empty
// (candidateRows reads the cells on both sides of a particle's cell without clamping).
TEST(NeighborGrid, ListsAreExactForParticlesOnTheContainerWalls) {
  const auto classes = sph::thesisPreset().levelProps();
  const float cell = static_cast<float>(std::max(classes[0].support, classes[1].support));
  sph::Aabb bounds;
  bounds.min = Eigen::Vector3d::Zero();
  bounds.max = Eigen::Vector3d::Constant(3.0 * cell);
  sph::NeighborGrid grid;
  grid.configure(bounds, cell, 1331);
  ASSERT_EQ(grid.cellCount(), 5u * 5u * 5u);

  // A lattice from wall to wall, walls included, whose spacing (0.3 cells) puts no pair exactly at
  // the reach of eq. (3.34), where the grid's and the brute force's roundings could differ.
  constexpr int kSteps = 10;
  sph::ParticleSet p(1331);
  for (int z = 0; z <= kSteps; ++z) {
    for (int y = 0; y <= kSteps; ++y) {
      for (int x = 0; x <= kSteps; ++x) {
        const sph::Level c = (x + y + z) % 3 == 0 ? sph::Level{1} : sph::Level{0};
        const sph::Vec3 at = sph::Vec3(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)) *
                             static_cast<float>(bounds.max.x() / kSteps);
        p.add(at, sph::Vec3::Zero(), c, classes[sph::levelIndex(c)]);
      }
    }
  }
  p.position[0] = bounds.max.cast<float>();  // the far corner, exactly
  grid.build(p);
  expectExactLists(p, listsOf(grid, p.size()));
}

// The vector pair loops stream a block's lists as one run of entries (thesis_stages_avx512.cpp):
// within a block, particle i + 1's list must start where i's ends; the dense cloud regrows the
// stride, so this holds after a rebuild too.
TEST(NeighborGrid, ListsOfABlockLieBackToBack) {
  const sph::ParticleSet p = denseCloud();
  sph::NeighborGrid grid = cloudGrid(p.size());
  grid.build(p);
  ASSERT_GT(sph::NeighborGrid::blockCount(p.size()), 2u);
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    if ((i + 1) % sph::NeighborGrid::kBlockSize == 0) continue;  // the next block starts afresh
    ASSERT_EQ(grid.neighbors(i + 1).data(), grid.neighbors(i).data() + grid.neighborCount(i)) << "particle " << i;
  }
}

// The relation of eq. (3.34) is symmetric, and the lists are complete.
TEST(NeighborGrid, NeighbourRelationIsSymmetric) {
  const sph::ParticleSet p = scatteredCloud();
  sph::Aabb bounds;
  bounds.max = Eigen::Vector3d::Constant(0.2);
  const auto classes = sph::thesisPreset().levelProps();
  sph::NeighborGrid grid;
  grid.configure(bounds, static_cast<float>(std::max(classes[0].support, classes[1].support)), p.size());
  grid.build(p);
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::uint32_t j : grid.neighbors(i)) {
      ASSERT_NE(j, i);
      const auto back = grid.neighbors(j);
      EXPECT_NE(std::find(back.begin(), back.end(), static_cast<std::uint32_t>(i)), back.end())
          << j << " is a neighbour of " << i << " but not the reverse";
      ++pairs;
    }
  }
  EXPECT_GT(pairs, 0u);
  // And the lists are complete: every pair within (hi + hj) / 2 is listed.
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto list = grid.neighbors(i);
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (j == i) continue;
      const float reach = 0.5f * (p.support[i] + p.support[j]);
      const bool close = (p.position[i] - p.position[j]).squaredNorm() <= reach * reach;
      const bool listed = std::find(list.begin(), list.end(), static_cast<std::uint32_t>(j)) != list.end();
      EXPECT_EQ(close, listed) << "pair " << i << ", " << j;
    }
  }
}

// A pair pass reads a neighbour's support only where the grid says the particle may have one of
// the other class (hasOtherSupport): never wrong where a listed neighbour has another support, and
// false for particles whose candidates are all of their own class, for any thread count.
// A pair pass reads a mixed list's levels in list order (NeighborGrid::neighborLevels): each is the
// level of the neighbour at that slot, in every vector form, through the stride's regrowth, for
// any thread count.
TEST(NeighborGrid, MixedListsCarryTheirNeighboursLevels) {
  for (const sph::ParticleSet& p : {denseCloud(), scatteredCloud()}) {
    for (int threads : {1, 2}) {
      sph::NeighborGrid grid = cloudGrid(p.size());
      withThreads(threads, [&] { grid.build(p); });
      std::size_t mixed = 0;
      for (std::size_t i = 0; i < p.size(); ++i) {
        if (!grid.hasOtherSupport(i)) continue;
        ++mixed;
        const auto list = grid.neighbors(i);
        const std::uint8_t* levels = grid.neighborLevels(i);
        for (std::size_t s = 0; s < list.size(); ++s) {
          ASSERT_EQ(levels[s], sph::levelIndex(p.level[list[s]]))
              << "particle " << i << ", slot " << s << ", " << threads << " threads";
        }
      }
      EXPECT_GT(mixed, p.size() / 4) << "both clouds mix the levels";
    }
  }
}

TEST(NeighborGrid, ParticlesAmongTheirOwnClassHaveNoOtherSupport) {
  const auto classes = sph::thesisPreset().levelProps();
  ASSERT_NE(classes[0].support, classes[1].support);
  // A bar 0.6 m long: L0 particles in its first third, L1 ones beyond.
  sph::ParticleSet p(3000);
  std::mt19937 rng(2024);
  std::uniform_real_distribution<float> along(0.0f, 0.6f), across(0.0f, 0.1f);
  while (p.size() < p.capacity()) {
    const sph::Vec3 x(along(rng), across(rng), across(rng));
    const sph::Level c = x.x() < 0.2f ? sph::Level{0} : sph::Level{1};
    p.add(x, sph::Vec3::Zero(), c, classes[sph::levelIndex(c)]);
  }
  sph::Aabb bounds;
  bounds.max = Eigen::Vector3d(0.6, 0.1, 0.1);
  const float cell = static_cast<float>(std::max(classes[0].support, classes[1].support));
  for (int threads : {1, 2}) {
    sph::NeighborGrid grid;
    grid.configure(bounds, cell, p.size());
    withThreads(threads, [&] { grid.build(p); });
    std::size_t mixed = 0, far_from_the_other = 0, far_flagged = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      bool has_other = false;
      for (std::uint32_t j : grid.neighbors(i)) has_other = has_other || p.support[j] != p.support[i];
      if (has_other) {
        ++mixed;
        EXPECT_TRUE(grid.hasOtherSupport(i)) << "particle " << i << " has a neighbour of the other class";
      }
      // Two cells and more from the classes' border no candidate is of the other class.
      if (std::abs(p.position[i].x() - 0.2f) > 2.0f * cell) {
        ++far_from_the_other;
        if (grid.hasOtherSupport(i)) ++far_flagged;
      }
    }
    EXPECT_GT(mixed, 0u) << "the border should hold mixed pairs";
    EXPECT_GT(far_from_the_other, p.size() / 2);
    EXPECT_EQ(far_flagged, 0u) << threads << " threads";
  }
}

}  // namespace
