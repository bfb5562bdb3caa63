// Sums over i < n in double, summed in blocks of a fixed size and the blocks in order: the same
// sums whatever the thread count (an OpenMP reduction's order depends on it), for the figures a
// solver's further steps depend on: conjugate gradients' step lengths, pbf's iteration count.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace sph {

// K sums at once: term(i) returns the K terms of element i. It is called exactly once for each i,
// so it may also update element i: a sweep and the sums of what it wrote take one pass over the
// arrays. `partials` is the caller's scratch, grown to K per block of 2,048 and never shrunk (no
// allocation once at the ceiling).
template <std::size_t K, class Term>
std::array<double, K> orderedSums(std::size_t n, std::vector<double>& partials, Term term) {
  constexpr std::size_t kBlock = 2048;
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  if (partials.size() < K * blocks) partials.resize(K * blocks);
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < blocks; ++b) {
    std::array<double, K> sum{};
    for (std::size_t i = b * kBlock; i < std::min(n, (b + 1) * kBlock); ++i) {
      const std::array<double, K> t = term(i);
      for (std::size_t k = 0; k < K; ++k) sum[k] += t[k];
    }
    std::copy(sum.begin(), sum.end(), partials.begin() + static_cast<std::ptrdiff_t>(K * b));
  }
  std::array<double, K> sum{};
  for (std::size_t b = 0; b < blocks; ++b) {
    for (std::size_t k = 0; k < K; ++k) sum[k] += partials[K * b + k];
  }
  return sum;
}

template <class Term>
double orderedSum(std::size_t n, std::vector<double>& partials, Term term) {
  return orderedSums<1>(n, partials, [&](std::size_t i) { return std::array<double, 1>{term(i)}; })[0];
}

}  // namespace sph
