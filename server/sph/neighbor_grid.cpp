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
  neighbor_start_.reserve(particle_capacity);
  neighbor_index_.resize(particle_capacity * stride_ + 16);
}

namespace scalar {
#include "sph/grid_binning.inc"
}  // namespace scalar

void NeighborGrid::bin(const ParticleSet& particles) {
  const std::size_t n = particles.size();
  const std::size_t cells = cellCount();
  particle_cell_.resize(n);
  cell_particles_.resize(n);
  neighbor_count_.resize(n);
  neighbor_start_.resize(n);
  for (auto* v : {&sorted_x_, &sorted_y_, &sorted_z_, &sorted_support_}) v->resize(n);
  // configure() sized the counts for the thread count of its time; a larger team needs more.
  const auto threads = static_cast<std::size_t>(omp_get_max_threads());
  if (thread_cursor_.size() < threads * cells) thread_cursor_.resize(threads * cells);
  cell_range_total_.resize(threads);
  const GridBinningForms forms =
      simdLevel() == SimdLevel::kAvx512 ? avx512::gridBinningForms() : scalar::gridBinningForms();
  const GridGeometry geometry{{origin_.x(), origin_.y(), origin_.z()}, inv_cell_size_, {dims_[0], dims_[1], dims_[2]}};

  // A counting sort shared by the threads, in one parallel region. Done serially between two
  // parallel loops, it left the other thread idle long enough to fall asleep (omp_wait.h), and
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

void NeighborGrid::build(const ParticleSet& particles) {
  bin(particles);
  const std::size_t n = particles.size();
  const ScanCandidatesFn scan = simdLevel() == SimdLevel::kAvx512 ? avx512::scanCandidates : scalar::scanCandidates;
  const SortedCandidates sorted{sorted_x_.data(), sorted_y_.data(), sorted_z_.data(), sorted_support_.data(),
                                cell_particles_.data()};
  for (;;) {
    if (neighbor_index_.size() < n * stride_) neighbor_index_.resize(n * stride_);
    group_scratch_.resize(static_cast<std::size_t>(omp_get_max_threads()));
    for (auto& scratch : group_scratch_) {
      if (scratch.size() < (kMaxScanGroup - 1) * (stride_ + 16)) scratch.resize((kMaxScanGroup - 1) * (stride_ + 16));
    }
    std::uint32_t max_count = 0;
    // Blocks of particles taken by whichever thread is free: the cost per particle varies with its
    // class and neighbour count, and adaptive runs keep the SMALL ones (the costly ones) together
    // at the end of the arrays, so fixed halves left one thread waiting for the other.
    const std::size_t blocks = blockCount(n);
#pragma omp parallel for schedule(dynamic, 1) reduction(max : max_count)
    for (std::size_t b = 0; b < blocks; ++b) {
      const std::size_t begin = b * kBlockSize;
      const std::size_t end = std::min(n, begin + kBlockSize);
      // The block packs its lists from the start of its particles' slots.
      std::size_t cursor = begin * stride_;
      const std::size_t region_end = end * stride_;
      CandidateRows rows;
      std::uint32_t* scratch = group_scratch_[static_cast<std::size_t>(omp_get_thread_num())].data();
      const std::size_t scratch_room = stride_ + 16;
      // A list keeps at most stride - 1 entries, so the ones before i used at most
      // (i - begin) (stride - 1) slots and list i always has stride slots left in the range.
      const auto place = [&](std::size_t i, std::uint32_t count) {
        max_count = std::max(max_count, count);
        neighbor_count_[i] = std::min<std::uint32_t>(count, static_cast<std::uint32_t>(stride_ - 1));
        neighbor_start_[i] = cursor;
        cursor += neighbor_count_[i];
      };
      // The lists of a group after its first wait in scratch until the ones before are placed.
      const auto placeGroup = [&](std::size_t i, const ScanTarget* targets, std::size_t count) {
        place(i, targets[0].count);
        for (std::size_t g = 1; g < count; ++g) {
          std::copy_n(targets[g].out,
                      std::min<std::uint32_t>(targets[g].count, static_cast<std::uint32_t>(stride_ - 1)),
                      neighbor_index_.data() + cursor);
          place(i + g, targets[g].count);
        }
      };
      for (std::size_t i = begin; i < end;) {
        // Particles in cell order (the arrays are re-sorted every few steps) come in runs that
        // share one cell and so one set of candidate rows; up to kMaxScanGroup of them scan together.
        const std::uint32_t cell = particle_cell_[i];
        if (i == begin || cell != particle_cell_[i - 1]) rows = candidateRows(cell);
        std::size_t run = 1;
        while (run < kMaxScanGroup && i + run < end && particle_cell_[i + run] == cell) ++run;
        // The first list goes in place, the others to scratch.
        ScanTarget targets[kMaxScanGroup];
        for (std::size_t g = 0; g < run; ++g) {
          const std::size_t k = i + g;
          targets[g] = {particles.position[k],
                        particles.support[k],
                        static_cast<std::uint32_t>(k),
                        g == 0 ? neighbor_index_.data() + cursor : scratch + (g - 1) * scratch_room,
                        g == 0 ? region_end - cursor : scratch_room,
                        0};
        }
        scan(rows, sorted, targets, run, static_cast<std::uint32_t>(stride_ - 1));
        placeGroup(i, targets, run);
        i += run;
      }
    }
    // The last slot is scratch for the branch-free writes, so a full list must stay below it.
    if (max_count < stride_) break;
    // Rare: compression pushed some particle past the stride. Grow with headroom and redo.
    stride_ = static_cast<std::size_t>(max_count) + max_count / 2;
    ++stride_growths_;
  }
}

CandidateRows NeighborGrid::candidateRows(std::uint32_t cell) const {
  // cellsOf keeps particles off the border cells, so cell +- 1 along each axis exists: the rows are
  // offsets from `cell`, with no division to recover its coordinates (the gaze method's LARGE
  // particles, about eight to a cell, ask for new rows every few particles).
  static_assert(kCellsPerSupport == 1, "the rows below are those of a 3 x 3 x 3 block");
  const std::ptrdiff_t row_step = dims_[0];
  const std::ptrdiff_t plane_step = row_step * dims_[1];
  CandidateRows out;
  for (std::ptrdiff_t dz = -1; dz <= 1; ++dz) {
    for (std::ptrdiff_t dy = -1; dy <= 1; ++dy) {
      // Cells centre - 1 .. centre + 1 of one row are contiguous in the sorted list.
      const auto centre = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(cell) + dz * plane_step + dy * row_step);
      out.begin[out.count] = cell_start_[centre - 1];
      out.end[out.count] = cell_start_[centre + 2];
      ++out.count;
    }
  }
  return out;
}

double NeighborGrid::meanNeighbors() const {
  if (neighbor_count_.empty()) return 0.0;
  double sum = 0.0;
  for (std::uint32_t c : neighbor_count_) sum += c;
  return sum / static_cast<double>(neighbor_count_.size());
}

}  // namespace sph
