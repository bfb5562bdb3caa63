#include "sph/adaptive/split_merge.h"

#include <algorithm>

#include <omp.h>

#include "sph/adaptive/decide.h"
#include "sph/adaptive/split_axis.h"
#include "sph/collision.h"
#include "sph/hashed_direction.h"
#include "sph/thread_share.h"

namespace sph {

namespace {

// Obstacles may sit where a child lands: push the child out as the step's collision would, without
// touching its velocity (split keeps velocities, eq. 3.39).
void keepOutOfObstacles(const Boundary& boundary, const BoxState& box, float radius, Vec3& x) {
  Vec3 unused_velocity = Vec3::Zero();
  collideBoundary(boundary, box, radius, x, unused_velocity);
}

}  // namespace

Vec3 splitDirection(std::uint32_t id) { return hashedUnitVector(id); }

void pairStragglers(const ParticleSet& p, std::span<const std::int8_t> decision, std::span<std::int32_t> partner,
                    float reach, Level coarsest, StragglerScratch& scratch) {
  // Each thread lists the stragglers of its contiguous index range at the start of that range
  // (branch-free: whether a particle is a straggler follows no pattern a predictor could learn);
  // the ranges are then closed up in thread order, so the list is in index order whatever the
  // thread count.
  const std::size_t n = p.size();
  std::vector<std::uint32_t>& lonely = scratch.lonely;
  if (lonely.size() < n) lonely.resize(n);
  std::vector<std::size_t>& ranges = scratch.ranges;  // per thread: begin, count
  ranges.assign(2 * static_cast<std::size_t>(omp_get_max_threads()), 0);
#pragma omp parallel
  {
    const ThreadShare share = threadShare(n);
    std::size_t count = 0;
    for (std::size_t i = share.begin; i < share.end; ++i) {
      lonely[share.begin + count] = static_cast<std::uint32_t>(i);
      count += (partner[i] < 0) & wantsMerge(decision[i], p.level[i], coarsest);
    }
    ranges[2 * share.thread] = share.begin;
    ranges[2 * share.thread + 1] = count;
  }
  std::size_t found = 0;
  for (std::size_t t = 0; 2 * t < ranges.size(); ++t) {
    // Moves down (found <= the range's start), so a forward copy is safe; none when in place.
    if (ranges[2 * t] != found) {
      std::copy_n(lonely.begin() + static_cast<std::ptrdiff_t>(ranges[2 * t]), ranges[2 * t + 1],
                  lonely.begin() + static_cast<std::ptrdiff_t>(found));
    }
    found += ranges[2 * t + 1];
  }
  // The pairing below is serial: a spray of thousands of isolated droplets must not stall the
  // step, so at most this many (the lowest indices, deterministically) pair per step.
  constexpr std::size_t kMaxStragglersPerStep = 512;
  const std::size_t count = std::min(found, kMaxStragglersPerStep);
  if (count < 2) return;
  const auto x = [&](std::uint32_t a) { return p.position[lonely[a]].x(); };
  // The sweep's bound: the farthest any straggler may look (the coarsest one's reach).
  float max_distance = 0.0f;
  for (std::size_t a = 0; a < count; ++a) max_distance = std::max(max_distance, reach * p.support[lonely[a]]);

  // Nearest other straggler of each: a sweep along x visits only the ones less than max_distance
  // away in x (the others are farther in 3D too), instead of all L^2 pairs; stragglers spread
  // along the water, so that is a few per straggler. The winner does not depend on the visiting
  // order: the least distance, ties to the lower position in `lonely` (the lower index).
  std::vector<std::uint32_t>& by_x = scratch.by_x;
  by_x.resize(count);
  for (std::uint32_t a = 0; a < count; ++a) by_x[a] = a;
  std::sort(by_x.begin(), by_x.end(),
            [&](std::uint32_t a, std::uint32_t b) { return x(a) < x(b) || (x(a) == x(b) && a < b); });
  std::vector<std::int32_t>& nearest = scratch.nearest;
  nearest.assign(count, -1);
  for (std::size_t s = 0; s < count; ++s) {
    const std::uint32_t a = by_x[s];
    const Vec3 xa = p.position[lonely[a]];
    const Level level = p.level[lonely[a]];
    const float own_reach = reach * p.support[lonely[a]];
    float best = own_reach * own_reach;
    const auto consider = [&](std::uint32_t b) {
      if (p.level[lonely[b]] != level) return;
      const float d2 = (xa - p.position[lonely[b]]).squaredNorm();
      if (d2 < best || (d2 == best && nearest[a] >= 0 && static_cast<std::int32_t>(b) < nearest[a])) {
        best = d2;
        nearest[a] = static_cast<std::int32_t>(b);
      }
    };
    for (std::size_t t = s + 1; t < count && x(by_x[t]) - xa.x() <= max_distance; ++t) consider(by_x[t]);
    for (std::size_t t = s; t-- > 0 && xa.x() - x(by_x[t]) <= max_distance;) consider(by_x[t]);
  }
  for (std::size_t a = 0; a < count; ++a) {
    const std::int32_t b = nearest[a];
    if (b >= 0 && nearest[static_cast<std::size_t>(b)] == static_cast<std::int32_t>(a)) {
      partner[lonely[a]] = static_cast<std::int32_t>(lonely[static_cast<std::size_t>(b)]);
    }
  }
}

SplitMergeCounts applySplitMerge(Simulation& sim, std::span<const std::int8_t> decision,
                                 std::span<const std::int32_t> partner, std::vector<std::uint8_t>& keep,
                                 std::vector<std::uint32_t>& split_list) {
  ParticleSet& p = sim.particles();
  const std::size_t n = p.size();
  const auto props = sim.params().levelProps();
  const auto below = [&](std::size_t i) { return asLevel(levelIndex(p.level[i]) - 1); };
  const auto above = [&](std::size_t i) { return asLevel(levelIndex(p.level[i]) + 1); };
  const auto radiusOf = [&](Level level) { return static_cast<float>(props[levelIndex(level)].radius); };
  const BoxState box = sim.boxNow();
  const Boundary& boundary = sim.scene().boundary;
  SplitMergeCounts counts;

  // The particles that split, in index order (a serial, branch-free scan): the k-th one's second
  // child takes slot k after the current end, so the layout (and every later sum) is the same for
  // any thread count.
  std::vector<std::uint32_t>& splitting = split_list;
  splitting.resize(n);
  std::uint32_t splits = 0;
  for (std::size_t i = 0; i < n; ++i) {
    splitting[splits] = static_cast<std::uint32_t>(i);
    splits += wantsSplit(decision[i], p.level[i]);
  }
  // Where the children go is the solver's choice (FluidSolver::splitPlacement): along the roomiest
  // axis among the parent's neighbours (split_axis.h) or along a direction drawn from the parent's
  // id. The step's neighbour lists serve (the adaptive step follows the solver's); lists of another
  // particle count (a second split or merge without a step between) are built again.
  const bool roomiest = sim.solver().splitPlacement() == SplitPlacement::kRoomiestAxis;
  if (roomiest && splits > 0 && sim.grid().neighborCounts().size() != n) sim.rebuildNeighbors();
  const std::size_t first_child = p.appendReset(splits);
  counts.splits = static_cast<int>(splits);

  // Split, eqs. (3.37)-(3.39), every attribute by its rule (particle_attributes.h); the children
  // sit at +- half the parent radius along the split axis, so the centre of mass stays put (but
  // for incompressible water in a box corner, below).
  // They are then 0.78 of their own lattice spacing apart (r = 0.62 spacings, eq. 3.7; a level's
  // spacing is 1.26 of the level below's), closer than a lattice's neighbours: the incompressible solvers then move
  // the fresh particles apart by position (local_placement.h). The roomiest axis reads the
  // neighbours' positions, so every offset is chosen before any parent moves: the first pass
  // keeps it in the child's slot (appended, so no neighbour list names it), the second places.
  if (splits > 0) {
    // Only the splitting particles, in small chunks: they cluster in index ranges.
#pragma omp parallel for schedule(dynamic, 32)
    for (std::uint32_t slot = 0; slot < splits; ++slot) {
      const std::size_t i = splitting[slot];
      const float wanted = 0.5f * p.radius[i];
      const float child_radius = radiusOf(below(i));
      p.position[first_child + slot] =
          roomiest ? roomiestChildOffset(p, sim.grid(), i, box, child_radius, wanted)
                   : childOffsetInBox(p.position[i], splitDirection(p.id[i]), box, child_radius, wanted);
    }
#pragma omp parallel for schedule(dynamic, 32)
    for (std::uint32_t slot = 0; slot < splits; ++slot) {
      const std::size_t i = splitting[slot];
      const std::size_t c = first_child + slot;
      const Vec3 offset = p.position[c];
      Vec3 a = p.position[i] + offset;
      Vec3 b = p.position[i] - offset;
      const float wanted = 0.5f * p.radius[i];
      if (roomiest && offset.squaredNorm() < 0.25f * wanted * wanted) {
        // Walls on three sides (a box corner) cut every axis short: children about the centre
        // would land on one point, and the doubled mass there kicks the water. One child keeps
        // the parent's centre, the other goes the children's distance into the box; the centre
        // of mass moves half a parent radius inwards.
        a = p.position[i] + 2.0f * wanted * awayFromNearestFaces(p.position[i], box);
        b = p.position[i];
      }
      const Level level = below(i);
      keepOutOfObstacles(boundary, box, radiusOf(level), a);
      keepOutOfObstacles(boundary, box, radiusOf(level), b);
      p.splitInto(i, c, level, props[levelIndex(level)]);
      p.position[i] = a;
      p.position[c] = b;
    }
  }

  // Merge, eqs. (3.40)-(3.43), every attribute by its rule: mass summed, position and velocity
  // averaged (equal masses, so the momentum m_i u_i + m_j u_j is kept). The lower index of each
  // mutual pair survives.
  keep.assign(p.size(), 1);
  int merges = 0;
#pragma omp parallel for schedule(static) reduction(+ : merges)
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t j = partner[i];
    if (j < 0 || static_cast<std::size_t>(j) <= i ||
        partner[static_cast<std::size_t>(j)] != static_cast<std::int32_t>(i)) {
      continue;
    }
    const auto k = static_cast<std::size_t>(j);
    const Level level = above(i);
    p.mergeInto(i, k, level, props[levelIndex(level)]);
    keepOutOfObstacles(boundary, box, radiusOf(level), p.position[i]);
    keep[k] = 0;
    ++merges;
  }
  counts.merges = merges;
  if (merges > 0) {
    // A few merges per step are the rule: move the last particles into the holes rather than
    // shifting every attribute of every particle.
    p.swapRemove(keep);
  }
  return counts;
}

}  // namespace sph
