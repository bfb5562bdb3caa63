// Neighbour search on a uniform grid: a counting sort bins particles into cells (deterministic,
// the same order for any thread count), then a parallel pass writes each particle's neighbours
// into one flat array, the lists packed back to back within blocks of 256 particles. Neighbours
// follow the adaptive criterion |ri - rj| <= (hi + hj) / 2, eq. (3.34), so mixed L0 and L1
// particles need no second code path.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "sph/boundary.h"
#include "sph/neighbor_scan.h"
#include "sph/particles.h"

namespace sph {

class NeighborGrid {
 public:
  // Sizes the grid to cover `bounds` with cubic cells of edge `cell_size` (>= the largest support
  // radius). Allocates; call outside the step.
  void configure(const Aabb& bounds, float cell_size, std::size_t particle_capacity);

  // Bins the particles and rebuilds every neighbour list. Allocates only when some particle has
  // more neighbours than the current stride, the most one list may hold (the stride then grows
  // and the pass is redone).
  void build(const ParticleSet& particles);

  // Bins the particles only (no neighbour lists): cellOrder() then gives the order to permute
  // the particle arrays into. The lists are stale until the next build().
  void bin(const ParticleSet& particles);

  // Neighbours of particle i, excluding i itself, in a deterministic order.
  std::span<const std::uint32_t> neighbors(std::size_t i) const {
    return {neighbor_index_.data() + neighbor_start_[i], neighbor_count_[i]};
  }
  std::uint32_t neighborCount(std::size_t i) const { return neighbor_count_[i]; }
  // The levels of particle i's neighbours, in list order, where hasOtherSupport(i) (elsewhere
  // stale). At least 16 bytes stay readable past any list, so a pass may load whole lanes.
  const std::uint8_t* neighborLevels(std::size_t i) const { return neighbor_level_.data() + neighbor_start_[i]; }

  // Whether some neighbour of particle i may have another support radius than i (the other size
  // class: a mixed pair, eq. (3.35)); false where none of its candidates has (it is among its
  // own class only), and there a pair pass needs no neighbour's support.
  bool hasOtherSupport(std::size_t i) const { return other_support_[i] != 0; }

  // Where particle i's list starts among the grid's slotCount() slots: a value per pair computed
  // once a build (dfsph's kernel gradients) can be kept in an array of its own at the same slots.
  std::size_t neighborSlot(std::size_t i) const { return neighbor_start_[i]; }
  std::size_t slotCount() const { return neighbor_index_.size(); }

  // Particles come in blocks of kBlockSize (the last one shorter) whose lists lie back to back:
  // particle i + 1's list starts where i's ends when both are in one block. Block b holds
  // particles [b kBlockSize, min(n, (b + 1) kBlockSize)).
  static constexpr std::size_t kBlockSize = 256;
  static std::size_t blockCount(std::size_t particles) { return (particles + kBlockSize - 1) / kBlockSize; }
  std::span<const std::uint32_t> neighborCounts() const { return neighbor_count_; }

  // Particle indices sorted by cell: the order to permute the particle arrays into.
  std::span<const std::uint32_t> cellOrder() const { return cell_particles_; }

  float cellSize() const { return cell_size_; }
  std::size_t cellCount() const { return cell_start_.empty() ? 0 : cell_start_.size() - 1; }
  std::size_t stride() const { return stride_; }
  std::size_t strideGrowths() const { return stride_growths_; }
  double meanNeighbors() const;

 private:
  // support_run_end_ for the cell order bin() left.
  void findSupportRuns();

  // Cells are one (largest) support radius wide, so a particle's candidates lie in 9 rows of 3
  // cells. Half-radius cells (25 rows of 5) test fewer candidates, but each row costs its setup
  // and a partly empty 16-lane batch, and they were slower (docs/performance.md).
  // A particle's candidates: the particles of the 27 cells around its cell, as 9 rows of 3 cells,
  // each row a contiguous range of the sorted arrays (neighbor_scan.h).
  static constexpr int kCellsPerSupport = 1;
  static_assert(CandidateRows::kMaxRows == (2 * kCellsPerSupport + 1) * (2 * kCellsPerSupport + 1));

  Eigen::Vector3f origin_ = Eigen::Vector3f::Zero();
  float cell_size_ = 1.0f;
  float inv_cell_size_ = 1.0f;
  int dims_[3] = {1, 1, 1};
  std::size_t stride_ = 96;
  std::size_t stride_growths_ = 0;

  std::vector<std::uint32_t> cell_start_;      // cells + 1 offsets into cell_particles_
  std::vector<std::uint32_t> cell_particles_;  // particle indices grouped by cell
  std::vector<std::uint32_t> particle_cell_;   // cell of each particle
  // The counting sort's per-thread counts, then write cursors: thread t's at [t cells, (t + 1) cells).
  std::vector<std::uint32_t> thread_cursor_;
  std::vector<std::uint32_t> cell_range_total_;  // per thread: particles in its share of the cells
  std::vector<std::uint32_t> cell_sum_;          // per cell: particles, then a running cursor
  // Position and support radius of cell_particles_[k] at k, one array per coordinate: the candidate
  // loop reads memory in order, 16 candidates per AVX-512 instruction where the CPU has it.
  std::vector<float> sorted_x_, sorted_y_, sorted_z_, sorted_support_;
  std::vector<std::uint32_t> support_run_end_;  // BlockLists::support_run_end
  // Per thread: the lists of a group after its first, (kMaxScanGroup - 1) x (stride + 16) slots.
  std::vector<std::vector<std::uint32_t>> group_scratch_;
  std::vector<std::uint32_t> neighbor_count_;
  std::vector<std::uint8_t> other_support_;  // hasOtherSupport, per particle
  std::vector<std::size_t> neighbor_start_;  // where each list begins in neighbor_index_
  // Room for particles x stride_. A block's particles [b, e) own slots [b, e) x stride_ and pack
  // their lists from the start of that range: the pair loops then stream the lists instead of
  // touching a fresh cache line for each particle (a fixed stride left most of each row empty).
  std::vector<std::uint32_t> neighbor_index_;
  std::vector<std::uint8_t> neighbor_level_;  // neighborLevels: the level at each slot of neighbor_index_
  std::vector<std::int32_t> level_;           // each particle's level, as the level fill gathers it
};

// `seeds` and their neighbours in `grid`, ascending, into `out`: marks (`mark`, scratch, sized to
// the grid's particles and cleared here) scanned in index order, which for the few thousand
// particles a placement or a split pass reaches costs less than sorting a list.
void collectNeighbourhoods(const NeighborGrid& grid, std::span<const std::uint32_t> seeds,
                           std::vector<std::uint8_t>& mark, std::vector<std::uint32_t>& out);

}  // namespace sph
