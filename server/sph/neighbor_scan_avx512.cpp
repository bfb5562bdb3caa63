// The AVX-512 form of the neighbour scan: 16 candidates per instruction, accepted ones compressed
// into the list.
#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>

#include "sph/neighbor_scan.h"
#include "sph/simd/avx512_lanes.h"
#include "sph/simd/avx512_target.h"

SPH_AVX512_BEGIN

namespace sph::avx512 {

namespace {

// A target's centre and half support in all 16 lanes, where its list goes, and how many
// candidates it has accepted so far.
struct LaneTarget {
  __m512 px, py, pz, half_h;
  __m512i self;
  std::uint32_t* out;
  std::size_t room;
  std::uint32_t count = 0;

  explicit LaneTarget(const ScanTarget& t)
      : px(_mm512_set1_ps(t.position.x())),
        py(_mm512_set1_ps(t.position.y())),
        pz(_mm512_set1_ps(t.position.z())),
        half_h(_mm512_set1_ps(0.5f * t.support)),
        self(_mm512_set1_epi32(static_cast<int>(t.self))),
        out(t.out),
        room(t.room) {}

  // Appends the candidates of one batch (x, y, z, half support, index on the live lanes) within
  // reach, eq. (3.34), in candidate order. Compress in a register and store all 16 lanes while
  // the range has room for them (a compress-store straight to memory is far slower on
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
[[gnu::always_inline]] inline void scanRows(const CandidateRows& rows, const SortedCandidates& sorted,
                                            ScanTarget* targets, std::uint32_t capacity) {
  std::array<LaneTarget, kTargets> lanes = [&]<std::size_t... g>(std::index_sequence<g...>) {
    return std::array<LaneTarget, kTargets>{LaneTarget(targets[g])...};
  }
  (std::make_index_sequence<kTargets>{});
  // Locals: the list stores are __m512i, which may alias anything, so values read through
  // `sorted` or `rows` would be loaded again after every store.
  const float* const sx = sorted.x;
  const float* const sy = sorted.y;
  const float* const sz = sorted.z;
  const float* const support = sorted.support;
  const std::uint32_t* const index = sorted.index;
  const __m512 half = _mm512_set1_ps(0.5f);
  for (int r = 0; r < rows.count; ++r) {
    const std::uint32_t row_end = rows.end[r];
    for (std::uint32_t k = rows.begin[r]; k < row_end; k += 16) {
      const std::uint32_t left = row_end - k;
      const __mmask16 live = lanes::liveLanes(left);
      const __m512 x = _mm512_maskz_loadu_ps(live, sx + k);
      const __m512 y = _mm512_maskz_loadu_ps(live, sy + k);
      const __m512 z = _mm512_maskz_loadu_ps(live, sz + k);
      const __m512 half_hj = _mm512_mul_ps(_mm512_maskz_loadu_ps(live, support + k), half);
      const __m512i j = _mm512_maskz_loadu_epi32(live, index + k);
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

// The levels of a list's neighbours, in list order (neighbor_block.inc): 16 gathered at a time,
// none written past the list (the next block's lists may belong to another thread).
[[gnu::always_inline]] inline void fillLevels(const std::uint32_t* list, std::uint32_t count, const std::int32_t* level,
                                              std::uint8_t* out) {
  for (std::uint32_t b = 0; b < count; b += 16) {
    const __mmask16 live = lanes::liveLanes(count - b);
    const __m512i j = _mm512_maskz_loadu_epi32(live, list + b);
    const __m512i k = _mm512_mask_i32gather_epi32(_mm512_setzero_si512(), live, j, level, 4);
    _mm_mask_storeu_epi8(out + b, live, _mm512_cvtepi32_epi8(k));
  }
}

}  // namespace

void scanCandidates(const CandidateRows& rows, const SortedCandidates& sorted, ScanTarget* targets,
                    std::size_t target_count, std::uint32_t capacity) {
  scanGroup(rows, sorted, targets, target_count, capacity);
}

#include "sph/neighbor_block.inc"

NeighborScanForms neighborScanForms() { return {buildBlockLists}; }

}  // namespace sph::avx512

SPH_AVX512_END
