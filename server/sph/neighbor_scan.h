// The list pass of the neighbour search (neighbor_grid.h): for a block of particles, the
// candidates of each cell's particles tested against them, eq. (3.34), and the accepted ones
// written to their lists. Scalar, AVX2 and AVX-512 forms (simd_level.h), chosen by NeighborGrid::build.
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
// The scalar form may write one slot past the list (at most index `capacity`), the AVX2 and
// AVX-512 forms up to 8 and 16 while the target's `room` allows; all set each target's count.
namespace scalar {
void scanCandidates(const CandidateRows& rows, const SortedCandidates& sorted, ScanTarget* targets,
                    std::size_t target_count, std::uint32_t capacity);
}  // namespace scalar
namespace avx2 {
void scanCandidates(const CandidateRows& rows, const SortedCandidates& sorted, ScanTarget* targets,
                    std::size_t target_count, std::uint32_t capacity);
}  // namespace avx2
namespace avx512 {
void scanCandidates(const CandidateRows& rows, const SortedCandidates& sorted, ScanTarget* targets,
                    std::size_t target_count, std::uint32_t capacity);
}  // namespace avx512

// What the list pass of one block reads and writes (NeighborGrid's arrays).
struct BlockLists {
  const std::uint32_t* particle_cell;  // cell of each particle
  const std::uint32_t* cell_start;     // cells + 1 offsets into the cell-sorted arrays
  int row_step;                        // cells per row (x), and per plane (x y)
  int plane_step;
  SortedCandidates sorted;
  const Vec3* position;
  const float* support;
  // In cell order: where the run of candidates with candidate k's support radius ends (one past
  // its last), so that a row of candidates shows at once whether it holds one support or two.
  const std::uint32_t* support_run_end;
  std::uint32_t* neighbor_index;  // particles x stride slots
  std::uint32_t* neighbor_count;
  std::uint8_t* other_support;  // per particle: 1 where its candidates have another support than its own
  std::size_t* neighbor_start;
  std::size_t stride;  // slots per particle; a list keeps at most stride - 1 entries
  // Each particle's level, and per slot the level of the neighbour there (NeighborGrid::neighborLevels),
  // written for the particles with another support among their candidates.
  const std::int32_t* level;
  std::uint8_t* neighbor_level;
};

// Writes the lists of particles [begin, end), and whether each one's candidates hold another
// support than its own (NeighborGrid::hasOtherSupport), a block whose particles own slots
// [begin, end) x stride and pack their lists from its start; `scratch` holds the lists of a group
// after its first, (kMaxScanGroup - 1) x (stride + 16) slots. Returns the longest true count (one
// at or past stride - 1 means some list was cut: the caller grows the stride and redoes the pass).
namespace scalar {
std::uint32_t buildBlockLists(const BlockLists& job, std::size_t begin, std::size_t end, std::uint32_t* scratch);
}  // namespace scalar
namespace avx2 {
std::uint32_t buildBlockLists(const BlockLists& job, std::size_t begin, std::size_t end, std::uint32_t* scratch);
}  // namespace avx2
namespace avx512 {
std::uint32_t buildBlockLists(const BlockLists& job, std::size_t begin, std::size_t end, std::uint32_t* scratch);
}  // namespace avx512

// The neighbour scan's passes as one form (simd_level.h).
struct NeighborScanForms {
  std::uint32_t (*buildBlockLists)(const BlockLists& job, std::size_t begin, std::size_t end, std::uint32_t* scratch);
};
namespace scalar {
NeighborScanForms neighborScanForms();
}  // namespace scalar
namespace avx2 {
NeighborScanForms neighborScanForms();
}  // namespace avx2
namespace avx512 {
NeighborScanForms neighborScanForms();
}  // namespace avx512
// The forms this CPU runs.
NeighborScanForms neighborScanForms();

}  // namespace sph
