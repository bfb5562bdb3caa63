// sum_i term(i) in double, summed in blocks of a fixed size and the blocks in order: the same sum
// whatever the thread count (an OpenMP reduction's order depends on it), for the figures a
// solver's further steps depend on: conjugate gradients' step lengths, pbf's iteration count.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace sph {

template <class Term>
double orderedSum(std::size_t n, Term term) {
  constexpr std::size_t kBlock = 2048;
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<double> partial(blocks, 0.0);
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < blocks; ++b) {
    double sum = 0.0;
    for (std::size_t i = b * kBlock; i < std::min(n, (b + 1) * kBlock); ++i) sum += term(i);
    partial[b] = sum;
  }
  double sum = 0.0;
  for (const double v : partial) sum += v;
  return sum;
}

}  // namespace sph
