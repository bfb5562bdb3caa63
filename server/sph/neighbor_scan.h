// The inner loop of the neighbour search (neighbor_grid.h): the candidates of one cell's particles
// tested against them, eq. (3.34), and the accepted ones written to their lists. Scalar and
// AVX-512 forms (simd_level.h), chosen by NeighborGrid::build.
#pragma once

#include <cstddef>
#include <cstdint>

#include "sph/particles.h"

namespace sph {

// The candidates of a particle: the particles of the 27 cells around its cell, as 9 rows of 3
// cells, each row a contiguous range of the cell-sorted arrays.
struct CandidateRows {
  static constexpr int kMaxRows = 9;
  std::uint32_t begin[kMaxRows];
  std::uint32_t end[kMaxRows];
  int count = 0;
};

// The cell-sorted copies the scan reads in order: position and support radius of the k-th
// particle in cell order, and its index.
struct SortedCandidates {
  const float* x;
  const float* y;
  const float* z;
  const float* support;
  const std::uint32_t* index;
};

// One particle whose list a scan writes.
struct ScanTarget {
  Vec3 position;
  float support;
  std::uint32_t self;   // its index (never its own neighbour)
  std::uint32_t* out;   // where its list goes
  std::size_t room;     // slots from `out` that belong to it (its block's range, or scratch)
  std::uint32_t count;  // out: candidates accepted (past `capacity` the writes stop, the count goes on)
};

// Particles of one cell scanned together (up to kMaxScanGroup share the candidate rows).
inline constexpr std::size_t kMaxScanGroup = 2;

// Appends to each target's list, in candidate order, every candidate j != self with
// |x - x_j| <= (h + h_j) / 2, eq. (3.34); at most `capacity` entries per list are written.
// The scalar form may write one slot past the list (at most index `capacity`), the AVX-512 form
// up to 16 while the target's `room` allows; both set each target's count.
using ScanCandidatesFn = void (*)(const CandidateRows& rows, const SortedCandidates& sorted, ScanTarget* targets,
                                  std::size_t target_count, std::uint32_t capacity);
namespace scalar {
void scanCandidates(const CandidateRows& rows, const SortedCandidates& sorted, ScanTarget* targets,
                    std::size_t target_count, std::uint32_t capacity);
}  // namespace scalar
namespace avx512 {
void scanCandidates(const CandidateRows& rows, const SortedCandidates& sorted, ScanTarget* targets,
                    std::size_t target_count, std::uint32_t capacity);
}  // namespace avx512

}  // namespace sph
