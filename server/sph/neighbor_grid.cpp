#include "sph/neighbor_grid.h"

#include <algorithm>
#if defined(__AVX512F__)
#include <immintrin.h>
#endif
#include <cmath>
#include <stdexcept>
#include <string>

namespace sph {

void NeighborGrid::configure(const Aabb& bounds, float cell_size, std::size_t particle_capacity) {
  if (!(cell_size > 0.0f) || !std::isfinite(cell_size)) {
    throw std::invalid_argument("neighbour grid: cell size must be finite and > 0");
  }
  cell_size_ = cell_size / kCellsPerSupport;
  inv_cell_size_ = 1.0f / cell_size_;
  // One spare cell on each side of the container; the search block is clamped to the grid.
  origin_ = bounds.min.cast<float>() - Eigen::Vector3f::Constant(cell_size_);
  std::size_t cells = 1;
  for (int a = 0; a < 3; ++a) {
    const double extent = bounds.max[a] - bounds.min[a];
    dims_[a] = static_cast<int>(std::ceil(extent / cell_size_)) + 2;
    cells *= static_cast<std::size_t>(dims_[a]);
  }
  if (cells > (std::size_t{1} << 28)) {
    throw std::invalid_argument("neighbour grid: box too large for the support radius (" +
                                std::to_string(cells) + " cells)");
  }
  cell_start_.assign(cells + 1, 0);
  cell_particles_.reserve(particle_capacity);
  particle_cell_.reserve(particle_capacity);
  for (auto* v : {&sorted_x_, &sorted_y_, &sorted_z_, &sorted_support_}) v->reserve(particle_capacity);
  neighbor_count_.reserve(particle_capacity);
  neighbor_start_.reserve(particle_capacity);
  neighbor_index_.resize(particle_capacity * stride_ + 16);
}

std::uint32_t NeighborGrid::cellOf(const Vec3& p) const {
  int c[3];
  for (int a = 0; a < 3; ++a) {
    const float f = (p[a] - origin_[a]) * inv_cell_size_;
    // NaN and out-of-grid positions land in the border cells (the caller reports NaN separately).
    c[a] = std::isfinite(f) ? std::clamp(static_cast<int>(f), 0, dims_[a] - 1) : 0;
  }
  return static_cast<std::uint32_t>((c[2] * dims_[1] + c[1]) * dims_[0] + c[0]);
}

void NeighborGrid::bin(const ParticleSet& particles) {
  const std::size_t n = particles.size();
  const std::size_t cells = cellCount();
  particle_cell_.resize(n);
  cell_particles_.resize(n);
  neighbor_count_.resize(n);
  neighbor_start_.resize(n);

#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) particle_cell_[i] = cellOf(particles.position[i]);

  // Counting sort (serial, so the order inside a cell is always ascending particle index).
  std::fill(cell_start_.begin(), cell_start_.end(), 0u);
  for (std::size_t i = 0; i < n; ++i) ++cell_start_[particle_cell_[i] + 1];
  for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
  {
    // cell_start_[c] doubles as the write cursor of cell c; restored afterwards.
    for (std::size_t i = 0; i < n; ++i) cell_particles_[cell_start_[particle_cell_[i]]++] = static_cast<std::uint32_t>(i);
    for (std::size_t c = cells; c > 0; --c) cell_start_[c] = cell_start_[c - 1];
    cell_start_[0] = 0;
  }
  for (auto* v : {&sorted_x_, &sorted_y_, &sorted_z_, &sorted_support_}) v->resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t j = cell_particles_[k];
    const Vec3& x = particles.position[j];
    sorted_x_[k] = x.x();
    sorted_y_[k] = x.y();
    sorted_z_[k] = x.z();
    sorted_support_[k] = particles.support[j];
  }
}

void NeighborGrid::build(const ParticleSet& particles) {
  bin(particles);
  const std::size_t n = particles.size();
  for (;;) {
    if (neighbor_index_.size() < n * stride_) neighbor_index_.resize(n * stride_);
    std::uint32_t max_count = 0;
    // Blocks of particles taken by whichever thread is free: the cost per particle varies with its
    // class and neighbour count, and adaptive runs keep the SMALL ones (the costly ones) together
    // at the end of the arrays, so fixed halves left one thread waiting for the other.
    const std::size_t blocks = (n + kBlockSize - 1) / kBlockSize;
#pragma omp parallel for schedule(dynamic, 1) reduction(max : max_count)
    for (std::size_t b = 0; b < blocks; ++b) {
      const std::size_t begin = b * kBlockSize;
      const std::size_t end = std::min(n, begin + kBlockSize);
      // The block packs its lists from the start of its particles' slots.
      std::size_t cursor = begin * stride_;
      const std::size_t region_end = end * stride_;
      CandidateRows rows;
      for (std::size_t i = begin; i < end; ++i) {
        // Particles in cell order (the arrays are re-sorted every few steps) come in runs that
        // share one cell and so one set of candidate rows.
        if (i == begin || particle_cell_[i] != particle_cell_[i - 1]) rows = candidateRows(particle_cell_[i]);
        const std::uint32_t count = scanCandidates(rows, particles.position[i], particles.support[i],
                                                   static_cast<std::uint32_t>(i), neighbor_index_.data() + cursor,
                                                   region_end - cursor);
        max_count = std::max(max_count, count);
        // A list keeps at most stride - 1 entries, so the ones before i used at most
        // (i - begin) (stride - 1) slots and list i always has stride slots left in the range.
        neighbor_count_[i] = std::min<std::uint32_t>(count, static_cast<std::uint32_t>(stride_ - 1));
        neighbor_start_[i] = cursor;
        cursor += neighbor_count_[i];
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
  const int cx = static_cast<int>(cell % static_cast<std::uint32_t>(dims_[0]));
  const int cy = static_cast<int>((cell / static_cast<std::uint32_t>(dims_[0])) % static_cast<std::uint32_t>(dims_[1]));
  const int cz = static_cast<int>(cell / static_cast<std::uint32_t>(dims_[0] * dims_[1]));
  constexpr int R = kCellsPerSupport;
  const int x0 = std::max(cx - R, 0);
  const int x1 = std::min(cx + R, dims_[0] - 1);
  CandidateRows out;
  for (int z = std::max(cz - R, 0); z <= std::min(cz + R, dims_[2] - 1); ++z) {
    for (int y = std::max(cy - R, 0); y <= std::min(cy + R, dims_[1] - 1); ++y) {
      // Cells x0..x1 of one row are contiguous in the sorted list.
      const std::size_t row = (static_cast<std::size_t>(z) * dims_[1] + y) * dims_[0];
      out.begin[out.count] = cell_start_[row + x0];
      out.end[out.count] = cell_start_[row + x1 + 1];
      ++out.count;
    }
  }
  return out;
}

#if defined(__AVX512F__) && !defined(SPH_SCALAR_NEIGHBORS)
std::uint32_t NeighborGrid::scanCandidates(const CandidateRows& rows, const Vec3& pi, float hi,
                                           std::uint32_t self, std::uint32_t* out, std::size_t room) const {
  // 16 candidates at a time; compress-store keeps the accepted ones in candidate order, so the
  // lists are the same as the scalar loop's (and the same for any thread count).
  const __m512 px = _mm512_set1_ps(pi.x());
  const __m512 py = _mm512_set1_ps(pi.y());
  const __m512 pz = _mm512_set1_ps(pi.z());
  const __m512 half_hi = _mm512_set1_ps(0.5f * hi);
  const __m512 half = _mm512_set1_ps(0.5f);
  const __m512i self_v = _mm512_set1_epi32(static_cast<int>(self));
  const auto capacity = static_cast<std::uint32_t>(stride_ - 1);
  std::uint32_t count = 0;
  for (int r = 0; r < rows.count; ++r) {
    for (std::uint32_t k = rows.begin[r]; k < rows.end[r]; k += 16) {
      const std::uint32_t left = rows.end[r] - k;
      const __mmask16 live = left >= 16 ? __mmask16(0xFFFF) : __mmask16((1u << left) - 1u);
      const __m512 dx = _mm512_sub_ps(_mm512_maskz_loadu_ps(live, sorted_x_.data() + k), px);
      const __m512 dy = _mm512_sub_ps(_mm512_maskz_loadu_ps(live, sorted_y_.data() + k), py);
      const __m512 dz = _mm512_sub_ps(_mm512_maskz_loadu_ps(live, sorted_z_.data() + k), pz);
      // reach = (hi + hj) / 2, eq. (3.34)
      const __m512 reach =
          _mm512_fmadd_ps(_mm512_maskz_loadu_ps(live, sorted_support_.data() + k), half, half_hi);
      const __m512 r2 = _mm512_fmadd_ps(dz, dz, _mm512_fmadd_ps(dy, dy, _mm512_mul_ps(dx, dx)));
      const __m512i j = _mm512_maskz_loadu_epi32(live, cell_particles_.data() + k);
      const __mmask16 accept = _mm512_mask_cmp_ps_mask(live, r2, _mm512_mul_ps(reach, reach), _CMP_LE_OQ) &
                               _mm512_cmpneq_epi32_mask(j, self_v);
      const auto accepted = static_cast<std::uint32_t>(__builtin_popcount(accept));
      // Compress in a register and store all 16 lanes while the block's range has room for them
      // (a compress-store straight to memory is several times slower on current cores; the lanes
      // past the list land where the next list will be written); near the end of the range
      // store only the accepted lanes, so no write reaches another block's range.
      if (count + 16 <= room) {
        _mm512_storeu_si512(out + count, _mm512_maskz_compress_epi32(accept, j));
      } else if (count + accepted <= capacity) {
        alignas(64) std::uint32_t lanes[16];
        _mm512_store_si512(lanes, _mm512_maskz_compress_epi32(accept, j));
        for (std::uint32_t a = 0; a < accepted; ++a) out[count + a] = lanes[a];
      }
      count += accepted;
    }
  }
  return count;
}
#else
std::uint32_t NeighborGrid::scanCandidates(const CandidateRows& rows, const Vec3& pi, float hi,
                                           std::uint32_t self, std::uint32_t* out, std::size_t /*room*/) const {
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
#endif

double NeighborGrid::meanNeighbors() const {
  if (neighbor_count_.empty()) return 0.0;
  double sum = 0.0;
  for (std::uint32_t c : neighbor_count_) sum += c;
  return sum / static_cast<double>(neighbor_count_.size());
}

}  // namespace sph
