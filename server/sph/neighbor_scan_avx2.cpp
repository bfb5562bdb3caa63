// The AVX2 form of the neighbour scan: 8 candidates per instruction, accepted ones compressed
// into the list through a permutation looked up by the acceptance mask (AVX2 has no compress).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "sph/neighbor_scan.h"
#include "sph/simd/avx2_lanes.h"
#include "sph/simd/avx2_target.h"

SPH_AVX2_BEGIN

namespace sph::avx2 {

namespace {

// For each 8-lane mask, the lanes it sets in order, one byte each (the rest 0): the permutation
// that packs the accepted lanes to the front. A table, not BMI2's pext, which is slow on AMD
// CPUs before Zen 3, the very ones this form is for.
constexpr std::array<std::uint64_t, 256> kCompress = [] {
  std::array<std::uint64_t, 256> table{};
  for (std::uint32_t m = 0; m < 256; ++m) {
    std::uint64_t packed = 0;
    int at = 0;
    for (std::uint64_t l = 0; l < 8; ++l) {
      if ((m >> l) & 1u) packed |= l << (8 * at++);
    }
    table[m] = packed;
  }
  return table;
}();

inline __m256i compress(std::uint32_t mask, __m256i v) {
  const __m256i order = _mm256_cvtepu8_epi32(_mm_cvtsi64_si128(static_cast<long long>(kCompress[mask])));
  return _mm256_permutevar8x32_epi32(v, order);
}

// A target's centre and half support in all 8 lanes, where its list goes, and how many
// candidates it has accepted so far.
struct LaneTarget {
  __m256 px, py, pz, half_h;
  __m256i self;
  std::uint32_t* out;
  std::size_t room;
  std::uint32_t count = 0;

  explicit LaneTarget(const ScanTarget& t)
      : px(_mm256_set1_ps(t.position.x())),
        py(_mm256_set1_ps(t.position.y())),
        pz(_mm256_set1_ps(t.position.z())),
        half_h(_mm256_set1_ps(0.5f * t.support)),
        self(_mm256_set1_epi32(static_cast<int>(t.self))),
        out(t.out),
        room(t.room) {}

  // Appends the candidates of one batch within reach, eq. (3.34), in candidate order, as the
  // AVX-512 form does: all 8 compressed lanes stored while the range has room for them, only the
  // accepted ones near its end, none past `capacity` (the count still grows).
  void accept(__m256 live, __m256 x, __m256 y, __m256 z, __m256 half_hj, __m256i j, std::uint32_t capacity) {
    const __m256 dx = _mm256_sub_ps(x, px);
    const __m256 dy = _mm256_sub_ps(y, py);
    const __m256 dz = _mm256_sub_ps(z, pz);
    const __m256 reach = _mm256_add_ps(half_h, half_hj);
    const __m256 r2 = _mm256_fmadd_ps(dz, dz, _mm256_fmadd_ps(dy, dy, _mm256_mul_ps(dx, dx)));
    const __m256 within = _mm256_and_ps(live, _mm256_cmp_ps(r2, _mm256_mul_ps(reach, reach), _CMP_LE_OQ));
    const __m256 other = _mm256_castsi256_ps(_mm256_cmpeq_epi32(j, self));
    const auto accepted_lanes = static_cast<std::uint32_t>(_mm256_movemask_ps(_mm256_andnot_ps(other, within)));
    const auto accepted = static_cast<std::uint32_t>(__builtin_popcount(accepted_lanes));
    if (count + 8 <= room) {
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + count), compress(accepted_lanes, j));
    } else if (count + accepted <= capacity) {
      alignas(32) std::uint32_t lanes[8];
      _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), compress(accepted_lanes, j));
      for (std::uint32_t a = 0; a < accepted; ++a) out[count + a] = lanes[a];
    }
    count += accepted;
  }
};

// Walks the candidate rows 8 at a time and offers each batch to every target (as the AVX-512
// form: a group of one cell's particles loads each batch once).
template <std::size_t kTargets>
[[gnu::always_inline]] inline void scanRows(const CandidateRows& rows, const SortedCandidates& sorted,
                                            ScanTarget* targets, std::uint32_t capacity) {
  std::array<LaneTarget, kTargets> lanes = [&]<std::size_t... g>(std::index_sequence<g...>) {
    return std::array<LaneTarget, kTargets>{LaneTarget(targets[g])...};
  }
  (std::make_index_sequence<kTargets>{});
  // Locals: the list stores are __m256i, which may alias anything (neighbor_scan_avx512.cpp).
  const float* const sx = sorted.x;
  const float* const sy = sorted.y;
  const float* const sz = sorted.z;
  const float* const support = sorted.support;
  const std::uint32_t* const index = sorted.index;
  const __m256 half = _mm256_set1_ps(0.5f);
  for (int r = 0; r < rows.count; ++r) {
    const std::uint32_t row_end = rows.end[r];
    for (std::uint32_t k = rows.begin[r]; k < row_end; k += 8) {
      const std::uint32_t left = row_end - k;
      const __m256 live = lanes2::liveLanes(left);
      const __m256i live_i = _mm256_castps_si256(live);
      const __m256 x = _mm256_maskload_ps(sx + k, live_i);
      const __m256 y = _mm256_maskload_ps(sy + k, live_i);
      const __m256 z = _mm256_maskload_ps(sz + k, live_i);
      const __m256 half_hj = _mm256_mul_ps(_mm256_maskload_ps(support + k, live_i), half);
      const __m256i j = _mm256_maskload_epi32(reinterpret_cast<const int*>(index + k), live_i);
      for (LaneTarget& t : lanes) t.accept(live, x, y, z, half_hj, j, capacity);
    }
  }
  for (std::size_t g = 0; g < kTargets; ++g) targets[g].count = lanes[g].count;
}

// The scan of one group, inlined into the block pass (neighbor_block.inc).
[[gnu::always_inline]] inline void scanGroup(const CandidateRows& rows, const SortedCandidates& sorted,
                                             ScanTarget* targets, std::size_t target_count, std::uint32_t capacity) {
  static_assert(kMaxScanGroup == 2, "the dispatch below knows groups of 1 and 2");
  if (target_count == 1) {
    scanRows<1>(rows, sorted, targets, capacity);
  } else {
    scanRows<2>(rows, sorted, targets, capacity);
  }
}

// The levels of a list's neighbours, in list order (neighbor_block.inc): 8 gathered at a time,
// the tail one by one, so none is written past the list (the next block's lists may belong to
// another thread).
[[gnu::always_inline]] inline void fillLevels(const std::uint32_t* list, std::uint32_t count, const std::int32_t* level,
                                              std::uint8_t* out) {
  std::uint32_t b = 0;
  for (; b + 8 <= count; b += 8) {
    const __m256i j = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(list + b));
    const __m256i k = _mm256_i32gather_epi32(reinterpret_cast<const int*>(level), j, 4);
    const __m128i words = _mm_packus_epi32(_mm256_castsi256_si128(k), _mm256_extracti128_si256(k, 1));
    _mm_storel_epi64(reinterpret_cast<__m128i*>(out + b), _mm_packus_epi16(words, words));
  }
  for (; b < count; ++b) out[b] = static_cast<std::uint8_t>(level[list[b]]);
}

}  // namespace

void scanCandidates(const CandidateRows& rows, const SortedCandidates& sorted, ScanTarget* targets,
                    std::size_t target_count, std::uint32_t capacity) {
  scanGroup(rows, sorted, targets, target_count, capacity);
}

#include "sph/neighbor_block.inc"

NeighborScanForms neighborScanForms() { return {buildBlockLists}; }

}  // namespace sph::avx2

SPH_AVX2_END
