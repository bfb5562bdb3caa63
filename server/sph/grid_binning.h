// The vectorisable passes of the neighbour grid's counting sort (NeighborGrid::bin), one form per
// instruction set (simd_level.h), the same source for both (grid_binning.inc).
#pragma once

#include <cstddef>
#include <cstdint>

namespace sph {

// Where the grid lies: the corner of its cell 0, 1 / cell edge, and cells per axis (the
// container spans cells 1 .. dims - 2; the outermost layer stays empty).
struct GridGeometry {
  float origin[3];
  float inv_cell_size;
  int dims[3];
};

// The passes, as functions of the arrays they read and write (thread t's counts lie at
// counts + t cells):
//   cellsOf           the cell of each particle of [begin, end)
//   sumCellCounts     sums[c] = particles of cell c over the team's counts, c in [begin, end);
//                     returns their total
//   placeCellCursors  cell starts from `offset`, then each thread's counts become its cursors
struct GridBinningForms {
  void (*cellsOf)(const GridGeometry& grid, const float* xyz, std::size_t begin, std::size_t end, std::uint32_t* out);
  std::uint32_t (*sumCellCounts)(const std::uint32_t* counts, std::size_t team, std::size_t cells, std::size_t begin,
                                 std::size_t end, std::uint32_t* sums);
  void (*placeCellCursors)(std::uint32_t* counts, std::size_t team, std::size_t cells, std::size_t begin,
                           std::size_t end, std::uint32_t offset, std::uint32_t* sums, std::uint32_t* starts);
};

namespace scalar {
GridBinningForms gridBinningForms();
}  // namespace scalar
namespace avx2 {
GridBinningForms gridBinningForms();
}  // namespace avx2
namespace avx512 {
GridBinningForms gridBinningForms();
}  // namespace avx512
// The forms this CPU runs (simd_level.h).
GridBinningForms gridBinningForms();

}  // namespace sph
