#include "sph/neighbor_scan.h"

#include <algorithm>
#include <cstddef>

#include "sph/simd/simd_level.h"

namespace sph::scalar {

namespace {

std::uint32_t scanOne(const CandidateRows& rows, const SortedCandidates& sorted, const ScanTarget& t,
                      std::uint32_t capacity) {
  std::uint32_t count = 0;
  for (int r = 0; r < rows.count; ++r) {
    for (std::uint32_t k = rows.begin[r]; k < rows.end[r]; ++k) {
      const float dx = sorted.x[k] - t.position.x();
      const float dy = sorted.y[k] - t.position.y();
      const float dz = sorted.z[k] - t.position.z();
      const float reach = 0.5f * (t.support + sorted.support[k]);  // eq. (3.34)
      const std::uint32_t j = sorted.index[k];
      // Branch-free: about a third of the candidates are accepted, in no predictable pattern, so
      // a branch here mispredicts often. Write always, advance the cursor only on acceptance.
      const bool accept = (dx * dx + dy * dy + dz * dz <= reach * reach) & (j != t.self);
      t.out[std::min<std::uint32_t>(count, capacity)] = j;
      count += accept;
    }
  }
  return count;
}

// The scan of one group, inlined into the block pass (neighbor_block.inc).
inline void scanGroup(const CandidateRows& rows, const SortedCandidates& sorted, ScanTarget* targets,
                      std::size_t target_count, std::uint32_t capacity) {
  for (std::size_t g = 0; g < target_count; ++g) targets[g].count = scanOne(rows, sorted, targets[g], capacity);
}

// The levels of a list's neighbours, in list order (neighbor_block.inc).
inline void fillLevels(const std::uint32_t* list, std::uint32_t count, const std::int32_t* level, std::uint8_t* out) {
  for (std::uint32_t s = 0; s < count; ++s) out[s] = static_cast<std::uint8_t>(level[list[s]]);
}

}  // namespace

void scanCandidates(const CandidateRows& rows, const SortedCandidates& sorted, ScanTarget* targets,
                    std::size_t target_count, std::uint32_t capacity) {
  scanGroup(rows, sorted, targets, target_count, capacity);
}

#include "sph/neighbor_block.inc"

NeighborScanForms neighborScanForms() { return {buildBlockLists}; }

}  // namespace sph::scalar

sph::NeighborScanForms sph::neighborScanForms() {
  return formsForThisCpu(scalar::neighborScanForms, avx2::neighborScanForms, avx512::neighborScanForms);
}
