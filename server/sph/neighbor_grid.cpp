#include "sph/neighbor_grid.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#if defined(__AVX512F__)
#include <immintrin.h>
#endif
#include <omp.h>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sph/avx512_lanes.h"
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

void NeighborGrid::cellsOf(const float* __restrict xyz, std::size_t begin, std::size_t end,
                           std::uint32_t* __restrict out) const {
  // Locals, so GCC sees nothing in the loop can change them, and vectorises it.
  const float ox = origin_.x(), oy = origin_.y(), oz = origin_.z();
  const float inv = inv_cell_size_;
  const int dx = dims_[0], dy = dims_[1];
  // The container spans cells 1 .. dims - 2 (a point on its far wall may compute dims - 1, and
  // lies on that cell's lower face). Clamped as floats before the conversion: NaN and positions
  // below the grid land in cell 1, those above it (infinity included) in dims - 2, the outermost
  // inner cells (the caller reports NaN separately).
  const float top_x = static_cast<float>(dims_[0] - 2), top_y = static_cast<float>(dims_[1] - 2),
              top_z = static_cast<float>(dims_[2] - 2);
  const auto axis = [](float f, float top) {
    f = f >= 1.0f ? f : 1.0f;  // NaN too
    f = f < top + 1.0f ? f : top;
    return static_cast<int>(f);
  };
  for (std::size_t i = begin; i < end; ++i) {
    const int cx = axis((xyz[3 * i] - ox) * inv, top_x);
    const int cy = axis((xyz[3 * i + 1] - oy) * inv, top_y);
    const int cz = axis((xyz[3 * i + 2] - oz) * inv, top_z);
    out[i] = static_cast<std::uint32_t>((cz * dy + cy) * dx + cx);
  }
}

namespace {

// The passes of NeighborGrid::bin over cells [begin, end). There are more cells than particles
// (dambreak: 18,800 against 12,000-20,000), so they are written for GCC to vectorise, the scan
// included (omp simd inscan); restrict-qualified, as thread t's counts lie at counts + t cells.

// sums[c] = the particles of cell c, over the team's counts; returns their total.
std::uint32_t sumCellCounts(const std::uint32_t* __restrict counts, std::size_t team, std::size_t cells,
                            std::size_t begin, std::size_t end, std::uint32_t* __restrict sums) {
  for (std::size_t c = begin; c < end; ++c) sums[c] = counts[c];
  for (std::size_t t = 1; t < team; ++t) {
    const std::uint32_t* __restrict row = counts + t * cells;
    for (std::size_t c = begin; c < end; ++c) sums[c] += row[c];
  }
  std::uint32_t total = 0;
  for (std::size_t c = begin; c < end; ++c) total += sums[c];
  return total;
}

// Cell starts from `offset` (the particles of the cells before `begin`), then each thread's
// counts replaced by its write cursor: the cell's start plus the counts of the threads before it.
void placeCellCursors(std::uint32_t* __restrict counts, std::size_t team, std::size_t cells, std::size_t begin,
                      std::size_t end, std::uint32_t offset, std::uint32_t* __restrict sums,
                      std::uint32_t* __restrict starts) {
  std::uint32_t running = offset;
#pragma omp simd reduction(inscan, + : running)
  for (std::size_t c = begin; c < end; ++c) {
    starts[c] = running;
#pragma omp scan exclusive(running)
    running += sums[c];
  }
  for (std::size_t c = begin; c < end; ++c) sums[c] = starts[c];
  for (std::size_t t = 0; t < team; ++t) {
    std::uint32_t* __restrict row = counts + t * cells;
    for (std::size_t c = begin; c < end; ++c) {
      const std::uint32_t count = row[c];
      row[c] = sums[c];
      sums[c] += count;
    }
  }
}

}  // namespace

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
    cellsOf(particles.position.data()->data(), mine.begin, mine.end, particle_cell_.data());
    for (std::size_t i = mine.begin; i < mine.end; ++i) ++cursor[particle_cell_[i]];
#pragma omp barrier
    // Prefix sums over the cells, each thread over its share of them: first the particles in the
    // share, then (after every thread has its total) the cell starts and the per-thread cursors.
    const ThreadShare my_cells = threadShare(cells);
    cell_range_total_[mine.thread] =
        sumCellCounts(thread_cursor_.data(), team, cells, my_cells.begin, my_cells.end, cell_sum_.data());
#pragma omp barrier
    std::uint32_t offset = 0;
    for (std::size_t t = 0; t < mine.thread; ++t) offset += cell_range_total_[t];
    placeCellCursors(thread_cursor_.data(), team, cells, my_cells.begin, my_cells.end, offset, cell_sum_.data(),
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
  for (;;) {
    if (neighbor_index_.size() < n * stride_) neighbor_index_.resize(n * stride_);
    group_scratch_.resize(static_cast<std::size_t>(omp_get_max_threads()));
    for (auto& scratch : group_scratch_) {
      if (scratch.size() < (kMaxGroup - 1) * (stride_ + 16)) scratch.resize((kMaxGroup - 1) * (stride_ + 16));
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
      const auto placeGroup = [&](std::size_t i, const auto& counts) {
        place(i, counts[0]);
        for (std::size_t g = 1; g < counts.size(); ++g) {
          std::copy_n(scratch + (g - 1) * scratch_room,
                      std::min<std::uint32_t>(counts[g], static_cast<std::uint32_t>(stride_ - 1)),
                      neighbor_index_.data() + cursor);
          place(i + g, counts[g]);
        }
      };
      for (std::size_t i = begin; i < end;) {
        // Particles in cell order (the arrays are re-sorted every few steps) come in runs that
        // share one cell and so one set of candidate rows; up to kMaxGroup of them scan together.
        const std::uint32_t cell = particle_cell_[i];
        if (i == begin || cell != particle_cell_[i - 1]) rows = candidateRows(cell);
        std::size_t run = 1;
        while (run < kMaxGroup && i + run < end && particle_cell_[i + run] == cell) ++run;
        const auto first = static_cast<std::uint32_t>(i);
        std::uint32_t* out = neighbor_index_.data() + cursor;
        const std::size_t room = region_end - cursor;
        static_assert(kMaxGroup == 2, "the dispatch below knows groups of 1 and 2");
        if (run == 1) {
          placeGroup(i, scanCandidateGroup<1>(rows, particles, first, out, room, scratch, scratch_room));
        } else {
          placeGroup(i, scanCandidateGroup<2>(rows, particles, first, out, room, scratch, scratch_room));
        }
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

NeighborGrid::CandidateRows NeighborGrid::candidateRows(std::uint32_t cell) const {
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

#if defined(__AVX512F__) && !defined(SPH_SCALAR_NEIGHBORS)
namespace {

// One particle whose list a scan writes: its centre and half support in all 16 lanes, where its
// list goes, and how many candidates it has accepted so far.
struct ScanTarget {
  __m512 px, py, pz, half_h;
  __m512i self;
  std::uint32_t* out;
  std::size_t room;  // slots from `out` that belong to the particle's block (or scratch)
  std::uint32_t count = 0;

  ScanTarget(const Vec3& p, float h, std::uint32_t index, std::uint32_t* list, std::size_t slots)
      : px(_mm512_set1_ps(p.x())),
        py(_mm512_set1_ps(p.y())),
        pz(_mm512_set1_ps(p.z())),
        half_h(_mm512_set1_ps(0.5f * h)),
        self(_mm512_set1_epi32(static_cast<int>(index))),
        out(list),
        room(slots) {}

  // Appends the candidates of one batch (x, y, z, half support, index on the live lanes) within
  // reach, eq. (3.34), in candidate order. Compress in a register and store all 16 lanes while
  // the range has room for them (a compress-store straight to memory is several times slower on
  // current cores; the lanes past the list land where the next list will be written); near the
  // end of the range store only the accepted lanes, so no write leaves it. Past `capacity` the
  // writes stop but the count still grows (build() then regrows the stride).
  void accept(__mmask16 live, __m512 x, __m512 y, __m512 z, __m512 half_hj, __m512i j, std::uint32_t capacity) {
    const __m512 dx = _mm512_sub_ps(x, px);
    const __m512 dy = _mm512_sub_ps(y, py);
    const __m512 dz = _mm512_sub_ps(z, pz);
    const __m512 reach = _mm512_add_ps(half_h, half_hj);
    const __m512 r2 = _mm512_fmadd_ps(dz, dz, _mm512_fmadd_ps(dy, dy, _mm512_mul_ps(dx, dx)));
    const __mmask16 accepted_lanes =
        _mm512_mask_cmp_ps_mask(live, r2, _mm512_mul_ps(reach, reach), _CMP_LE_OQ) & _mm512_cmpneq_epi32_mask(j, self);
    const auto accepted = static_cast<std::uint32_t>(__builtin_popcount(accepted_lanes));
    if (count + 16 <= room) {
      _mm512_storeu_si512(out + count, _mm512_maskz_compress_epi32(accepted_lanes, j));
    } else if (count + accepted <= capacity) {
      alignas(64) std::uint32_t lanes[16];
      _mm512_store_si512(lanes, _mm512_maskz_compress_epi32(accepted_lanes, j));
      for (std::uint32_t a = 0; a < accepted; ++a) out[count + a] = lanes[a];
    }
    count += accepted;
  }
};

// Walks the candidate rows 16 at a time and offers each batch to every target: particles of one
// cell share their candidates, so a group of them loads each batch once, and their independent
// count chains overlap.
template <std::size_t kTargets>
void scanRows(const std::uint32_t* row_begin, const std::uint32_t* row_end, int rows, const float* sx, const float* sy,
              const float* sz, const float* support, const std::uint32_t* index,
              std::array<ScanTarget, kTargets>& targets, std::uint32_t capacity) {
  const __m512 half = _mm512_set1_ps(0.5f);
  for (int r = 0; r < rows; ++r) {
    for (std::uint32_t k = row_begin[r]; k < row_end[r]; k += 16) {
      const std::uint32_t left = row_end[r] - k;
      const __mmask16 live = lanes::liveLanes(left);
      const __m512 x = _mm512_maskz_loadu_ps(live, sx + k);
      const __m512 y = _mm512_maskz_loadu_ps(live, sy + k);
      const __m512 z = _mm512_maskz_loadu_ps(live, sz + k);
      const __m512 half_hj = _mm512_mul_ps(_mm512_maskz_loadu_ps(live, support + k), half);
      const __m512i j = _mm512_maskz_loadu_epi32(live, index + k);
      for (ScanTarget& t : targets) t.accept(live, x, y, z, half_hj, j, capacity);
    }
  }
}

}  // namespace

template <std::size_t kGroup>
std::array<std::uint32_t, kGroup> NeighborGrid::scanCandidateGroup(const CandidateRows& rows,
                                                                   const ParticleSet& particles, std::uint32_t first,
                                                                   std::uint32_t* out, std::size_t room,
                                                                   std::uint32_t* scratch,
                                                                   std::size_t scratch_room) const {
  // Particle first writes its list in place, particle first + g (g > 0) to scratch slice g - 1.
  const auto target = [&](std::size_t g) {
    const std::uint32_t i = first + static_cast<std::uint32_t>(g);
    return g == 0 ? ScanTarget(particles.position[i], particles.support[i], i, out, room)
                  : ScanTarget(particles.position[i], particles.support[i], i, scratch + (g - 1) * scratch_room,
                               scratch_room);
  };
  std::array<ScanTarget, kGroup> targets = [&]<std::size_t... g>(std::index_sequence<g...>) {
    return std::array<ScanTarget, kGroup>{target(g)...};
  }
  (std::make_index_sequence<kGroup>{});
  scanRows(rows.begin, rows.end, rows.count, sorted_x_.data(), sorted_y_.data(), sorted_z_.data(),
           sorted_support_.data(), cell_particles_.data(), targets, static_cast<std::uint32_t>(stride_ - 1));
  std::array<std::uint32_t, kGroup> counts;
  for (std::size_t g = 0; g < kGroup; ++g) counts[g] = targets[g].count;
  return counts;
}
#else
std::uint32_t NeighborGrid::scanCandidates(const CandidateRows& rows, const Vec3& pi, float hi, std::uint32_t self,
                                           std::uint32_t* out) const {
  const auto last_slot = static_cast<std::uint32_t>(stride_ - 1);
  std::uint32_t count = 0;
  for (int r = 0; r < rows.count; ++r) {
    for (std::uint32_t k = rows.begin[r]; k < rows.end[r]; ++k) {
      const float dx = sorted_x_[k] - pi.x();
      const float dy = sorted_y_[k] - pi.y();
      const float dz = sorted_z_[k] - pi.z();
      const float reach = 0.5f * (hi + sorted_support_[k]);  // eq. (3.34)
      const std::uint32_t j = cell_particles_[k];
      // Branch-free: about a third of the candidates are accepted, in no predictable pattern, so
      // a branch here mispredicts often. Write always, advance the cursor only on acceptance.
      const bool accept = (dx * dx + dy * dy + dz * dz <= reach * reach) & (j != self);
      out[std::min<std::uint32_t>(count, last_slot)] = j;
      count += accept;
    }
  }
  return count;
}

template <std::size_t kGroup>
std::array<std::uint32_t, kGroup> NeighborGrid::scanCandidateGroup(const CandidateRows& rows,
                                                                   const ParticleSet& particles, std::uint32_t first,
                                                                   std::uint32_t* out, std::size_t /*room*/,
                                                                   std::uint32_t* scratch,
                                                                   std::size_t scratch_room) const {
  std::array<std::uint32_t, kGroup> counts;
  for (std::size_t g = 0; g < kGroup; ++g) {
    const std::uint32_t i = first + static_cast<std::uint32_t>(g);
    counts[g] = scanCandidates(rows, particles.position[i], particles.support[i], i,
                               g == 0 ? out : scratch + (g - 1) * scratch_room);
  }
  return counts;
}
#endif

double NeighborGrid::meanNeighbors() const {
  if (neighbor_count_.empty()) return 0.0;
  double sum = 0.0;
  for (std::uint32_t c : neighbor_count_) sum += c;
  return sum / static_cast<double>(neighbor_count_.size());
}

}  // namespace sph
