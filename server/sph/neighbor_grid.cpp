#include "sph/neighbor_grid.h"

#include <omp.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>

#include "sph/grid_binning.h"
#include "sph/simd/simd_level.h"
#include "sph/thread_share.h"

namespace sph {

void NeighborGrid::configure(const Aabb& bounds, float cell_size, std::size_t particle_capacity) {
  if (!(cell_size > 0.0f) || !std::isfinite(cell_size)) {
    throw std::invalid_argument("neighbour grid: cell size must be finite and > 0");
  }
  cell_size_ = cell_size / kCellsPerSupport;
  inv_cell_size_ = 1.0f / cell_size_;
  // One spare cell on each side of the container, never given a particle (cellsOf), so every
  // particle's cell has a neighbour cell on each side and candidateRows needs no clamping.
  origin_ = bounds.min.cast<float>() - Eigen::Vector3f::Constant(cell_size_);
  std::size_t cells = 1;
  for (int a = 0; a < 3; ++a) {
    const double extent = bounds.max[a] - bounds.min[a];
    dims_[a] = std::max(static_cast<int>(std::ceil(extent / cell_size_)), 1) + 2;
    cells *= static_cast<std::size_t>(dims_[a]);
  }
  if (cells > (std::size_t{1} << 28)) {
    throw std::invalid_argument("neighbour grid: box too large for the support radius (" + std::to_string(cells) +
                                " cells)");
  }
  cell_start_.assign(cells + 1, 0);
  cell_sum_.assign(cells, 0);
  thread_cursor_.assign(static_cast<std::size_t>(omp_get_max_threads()) * cells, 0);
  cell_particles_.reserve(particle_capacity);
  particle_cell_.reserve(particle_capacity);
  for (auto* v : {&sorted_x_, &sorted_y_, &sorted_z_, &sorted_support_}) v->reserve(particle_capacity);
  neighbor_count_.reserve(particle_capacity);
  other_support_.reserve(particle_capacity);
  support_run_end_.reserve(particle_capacity);
  neighbor_start_.reserve(particle_capacity);
  level_.reserve(particle_capacity);
  neighbor_index_.resize(particle_capacity * stride_ + 16);
  neighbor_level_.resize(neighbor_index_.size());
}

void NeighborGrid::bin(const ParticleSet& particles) {
  const std::size_t n = particles.size();
  const std::size_t cells = cellCount();
  particle_cell_.resize(n);
  cell_particles_.resize(n);
  neighbor_count_.resize(n);
  other_support_.resize(n);
  neighbor_start_.resize(n);
  for (auto* v : {&sorted_x_, &sorted_y_, &sorted_z_, &sorted_support_}) v->resize(n);
  // configure() sized the counts for the thread count of its time; a larger team needs more.
  const auto threads = static_cast<std::size_t>(omp_get_max_threads());
  if (thread_cursor_.size() < threads * cells) thread_cursor_.resize(threads * cells);
  cell_range_total_.resize(threads);
  const GridBinningForms forms = gridBinningForms();
  const GridGeometry geometry{{origin_.x(), origin_.y(), origin_.z()}, inv_cell_size_, {dims_[0], dims_[1], dims_[2]}};

  // A counting sort shared by the threads, in one parallel region. Done serially between two
  // parallel loops, it left the other thread idle long enough to fall asleep (process/omp_wait.h), and
  // waking it for the loop after took longer than the sort itself. The result is the serial
  // sort's, whatever the thread count: thread t counts and places its own contiguous share of the
  // particles, at cursors that put its particles of a cell after those of threads 0 .. t - 1, so
  // the order inside a cell is ascending particle index.
#pragma omp parallel
  {
    const std::size_t team = static_cast<std::size_t>(omp_get_num_threads());
    const ThreadShare mine = threadShare(n);
    std::uint32_t* const cursor = thread_cursor_.data() + mine.thread * cells;
    std::fill_n(cursor, cells, 0u);
    forms.cellsOf(geometry, particles.position.data()->data(), mine.begin, mine.end, particle_cell_.data());
    for (std::size_t i = mine.begin; i < mine.end; ++i) ++cursor[particle_cell_[i]];
#pragma omp barrier
    // Prefix sums over the cells, each thread over its share of them: first the particles in the
    // share, then (after every thread has its total) the cell starts and the per-thread cursors.
    const ThreadShare my_cells = threadShare(cells);
    cell_range_total_[mine.thread] =
        forms.sumCellCounts(thread_cursor_.data(), team, cells, my_cells.begin, my_cells.end, cell_sum_.data());
#pragma omp barrier
    std::uint32_t offset = 0;
    for (std::size_t t = 0; t < mine.thread; ++t) offset += cell_range_total_[t];
    forms.placeCellCursors(thread_cursor_.data(), team, cells, my_cells.begin, my_cells.end, offset, cell_sum_.data(),
                           cell_start_.data());
#pragma omp barrier
    // Each particle to its place in cell order, with the copies the candidate scan reads: the
    // reads go in particle order, and the arrays are re-sorted into cell order every few steps,
    // so the writes mostly do too.
    for (std::size_t i = mine.begin; i < mine.end; ++i) {
      const std::uint32_t k = cursor[particle_cell_[i]]++;
      const Vec3& x = particles.position[i];
      cell_particles_[k] = static_cast<std::uint32_t>(i);
      sorted_x_[k] = x.x();
      sorted_y_[k] = x.y();
      sorted_z_[k] = x.z();
      sorted_support_[k] = particles.support[i];
    }
  }
  cell_start_[cells] = static_cast<std::uint32_t>(n);
}

void NeighborGrid::findSupportRuns() {
  const std::size_t n = sorted_support_.size();
  support_run_end_.resize(n);
  // From the back: each candidate's run ends where its successor's does, unless the successor's
  // support differs. Serial: one pass over the particles, small beside the scan.
  for (std::size_t k = n; k-- > 0;) {
    const bool same_as_next = k + 1 < n && sorted_support_[k + 1] == sorted_support_[k];
    support_run_end_[k] = same_as_next ? support_run_end_[k + 1] : static_cast<std::uint32_t>(k + 1);
  }
}

void NeighborGrid::build(const ParticleSet& particles) {
  bin(particles);
  findSupportRuns();
  const std::size_t n = particles.size();
  const auto build_block = neighborScanForms().buildBlockLists;
  level_.resize(n);
  for (std::size_t i = 0; i < n; ++i) level_[i] = levelIndex(particles.level[i]);
  const SortedCandidates sorted{sorted_x_.data(), sorted_y_.data(), sorted_z_.data(), sorted_support_.data(),
                                cell_particles_.data()};
  for (;;) {
    if (neighbor_index_.size() < n * stride_ + 16) neighbor_index_.resize(n * stride_ + 16);
    neighbor_level_.resize(neighbor_index_.size());
    group_scratch_.resize(static_cast<std::size_t>(omp_get_max_threads()));
    for (auto& scratch : group_scratch_) {
      if (scratch.size() < (kMaxScanGroup - 1) * (stride_ + 16)) scratch.resize((kMaxScanGroup - 1) * (stride_ + 16));
    }
    std::uint32_t max_count = 0;
    // Blocks of particles taken by whichever thread is free: the cost per particle varies with its
    // class and neighbour count, and adaptive runs keep the L0 ones (the costly ones) together
    // at the end of the arrays, so fixed halves left one thread waiting for the other.
    const BlockLists job{particle_cell_.data(),
                         cell_start_.data(),
                         dims_[0],
                         dims_[0] * dims_[1],
                         sorted,
                         particles.position.data(),
                         particles.support.data(),
                         support_run_end_.data(),
                         neighbor_index_.data(),
                         neighbor_count_.data(),
                         other_support_.data(),
                         neighbor_start_.data(),
                         stride_,
                         level_.data(),
                         neighbor_level_.data()};
    const std::size_t blocks = blockCount(n);
#pragma omp parallel for schedule(dynamic, 1) reduction(max : max_count)
    for (std::size_t b = 0; b < blocks; ++b) {
      std::uint32_t* scratch = group_scratch_[static_cast<std::size_t>(omp_get_thread_num())].data();
      max_count = std::max(max_count, build_block(job, b * kBlockSize, std::min(n, (b + 1) * kBlockSize), scratch));
    }
    // The last slot is scratch for the branch-free writes, so a full list must stay below it.
    if (max_count < stride_) break;
    // Rare: compression pushed some particle past the stride. Grow with headroom and redo.
    stride_ = static_cast<std::size_t>(max_count) + max_count / 2;
    ++stride_growths_;
  }
}

void collectNeighbourhoods(const NeighborGrid& grid, std::span<const std::uint32_t> seeds,
                           std::vector<std::uint8_t>& mark, std::vector<std::uint32_t>& out) {
  mark.assign(grid.neighborCounts().size(), 0);
  for (const std::uint32_t i : seeds) {
    mark[i] = 1;
    for (const std::uint32_t j : grid.neighbors(i)) mark[j] = 1;
  }
  out.clear();
  for (std::size_t i = 0; i < mark.size(); ++i) {
    if (mark[i] != 0) out.push_back(static_cast<std::uint32_t>(i));
  }
}

double NeighborGrid::meanNeighbors() const {
  if (neighbor_count_.empty()) return 0.0;
  double sum = 0.0;
  for (std::uint32_t c : neighbor_count_) sum += c;
  return sum / static_cast<double>(neighbor_count_.size());
}

}  // namespace sph
