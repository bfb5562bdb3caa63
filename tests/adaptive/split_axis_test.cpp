// Where a split on incompressible water puts its children (split_axis.h): on an L1 lattice away
// from the neighbours, at a free surface within the surface, at a wall along it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "sph/adaptive/split_axis.h"
#include "sph/neighbor_grid.h"
#include "sph/params.h"
#include "sph/particles.h"

namespace {

// An n^3 block of L1 particles on their rest lattice (the pbf preset's masses) pressed by
// 0.5 %, so that no neighbour lies on the support's edge (two spacings: rounding would take one
// side's and not the other's), its corner at the origin, in a box `room` wider than the block on
// every side.
struct LatticeBlock {
  int n;
  float spacing;  // the block's, 0.995 d_L
  float wanted;   // half the children's distance: half the L1 radius, as the split asks
  float margin;   // the L0 radius
  sph::ParticleSet particles;
  sph::NeighborGrid grid;
  sph::BoxState box;

  LatticeBlock(int n_, double room) : n(n_), particles(static_cast<std::size_t>(n_) * n_ * n_) {
    const sph::SimParams params = sph::pbfPreset();
    const auto classes = params.levelProps();
    const sph::LevelProps large = classes[sph::levelIndex(sph::Level{1})];
    spacing = 0.995f * static_cast<float>(std::cbrt(large.mass / params.rest_density));
    wanted = 0.5f * static_cast<float>(large.radius);
    margin = static_cast<float>(classes[sph::levelIndex(sph::Level{0})].radius);
    for (int z = 0; z < n; ++z) {
      for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
          particles.add(spacing * sph::Vec3(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)),
                        sph::Vec3::Zero(), sph::Level{1}, large);
        }
      }
    }
    const float extent = static_cast<float>(n - 1) * spacing;
    box.min = Eigen::Vector3f::Constant(-static_cast<float>(room));
    box.max = Eigen::Vector3f::Constant(extent + static_cast<float>(room));
    const double support = std::max(classes[0].support, classes[1].support);
    sph::Aabb bounds;
    bounds.min = Eigen::Vector3d::Constant(-room - 2.0 * support);
    bounds.max = Eigen::Vector3d::Constant(extent + room + 2.0 * support);
    grid.configure(bounds, static_cast<float>(support), particles.size());
    grid.build(particles);
  }

  std::size_t at(int x, int y, int z) const { return static_cast<std::size_t>((z * n + y) * n + x); }

  sph::Vec3 offsetOf(std::size_t i) const { return sph::roomiestChildOffset(particles, grid, i, box, margin, wanted); }

  // The nearest any particle of the block but i comes to either child of i.
  float roomAround(std::size_t i, const sph::Vec3& offset) const {
    float nearest = std::numeric_limits<float>::max();
    for (std::size_t j = 0; j < particles.size(); ++j) {
      if (j == i) continue;
      const sph::Vec3 r = particles.position[j] - particles.position[i];
      nearest = std::min({nearest, (r - offset).norm(), (r + offset).norm()});
    }
    return nearest;
  }
};

// Inside a lattice the children go along a cube's diagonal, their full distance out: each stays
// 0.86 d_L from the parent's neighbours, where along an axis it would come within 0.69 d_L.
TEST(SplitAxis, InsideALatticeTheChildrenGoAlongACubesDiagonal) {
  const LatticeBlock block(7, 1.0);
  const std::size_t i = block.at(3, 3, 3);
  const sph::Vec3 offset = block.offsetOf(i);
  EXPECT_NEAR(offset.norm(), block.wanted, 1e-5f * block.spacing);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(std::abs(offset[a]), block.wanted / std::sqrt(3.0f), 1e-5f * block.spacing);
  EXPECT_GT(block.roomAround(i, offset), 0.8f * block.spacing);
  EXPECT_LT(block.roomAround(i, block.wanted * sph::Vec3(1.0f, 0.0f, 0.0f)), 0.7f * block.spacing);
}

// At the free surface (the block's top layer, away from its sides: every neighbour below or
// beside) both children stay in the surface's plane: a child put above it, where the most room
// is, would stand off the water.
TEST(SplitAxis, AtTheFreeSurfaceTheChildrenStayInIt) {
  const LatticeBlock block(9, 1.0);
  for (int x : {3, 4, 5}) {
    const std::size_t i = block.at(x, 8, 4);
    const sph::Vec3 offset = block.offsetOf(i);
    EXPECT_NEAR(offset.y(), 0.0f, 1e-6f) << "x " << x;
    EXPECT_NEAR(offset.norm(), block.wanted, 1e-5f * block.spacing) << "x " << x;
  }
}

// A parent in the wall layer (the lattice's half spacing from the floor, all but the L0
// radius the children keep off it) splits along the floor, never into it.
TEST(SplitAxis, AtAWallTheChildrenGoAlongIt) {
  LatticeBlock block(7, 0.0);
  block.box.min.y() = -0.5f * block.spacing;
  const std::size_t i = block.at(3, 0, 3);
  const sph::Vec3 offset = block.offsetOf(i);
  EXPECT_NEAR(offset.y(), 0.0f, 1e-6f);
  EXPECT_NEAR(offset.norm(), block.wanted, 1e-5f * block.spacing);
  EXPECT_GE(block.particles.position[i].y() - std::abs(offset.y()), block.box.min.y() + block.margin - 1e-6f);
}

}  // namespace
