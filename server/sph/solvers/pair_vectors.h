// A vector for each neighbour pair, kept at the pair's slot in the neighbour lists
// (NeighborGrid::neighborSlot) by one pass for the passes that follow it at the same positions:
// dfsph's solves read the kernel gradients its density pass stored instead of evaluating the
// kernel again in each of their iterations. Where one pass reads what one wrote (pbf's lambda
// and correction) storing the three components cost more than it saved; pbf keeps the gradient
// factor alone, a float a pair (PbfArrays::pair_g; docs/performance.md). x at [0, S), y at
// [S, 2 S), z at [2 S, 3 S), S = slots; valid until the grid is rebuilt or the positions move.
#pragma once

#include <cstddef>
#include <vector>

#include "sph/neighbor_grid.h"

namespace sph {

struct PairVectors {
  float* data = nullptr;  // null: none kept, the passes evaluate the kernel
  std::size_t slots = 0;
};

// The storage, sized to the grid's slots after each build (allocates only when they grow).
class PairVectorStore {
 public:
  PairVectors fit(const NeighborGrid& grid) {
    values_.resize(3 * grid.slotCount());
    return {values_.data(), grid.slotCount()};
  }

 private:
  std::vector<float> values_;
};

}  // namespace sph
