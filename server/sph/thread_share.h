// A thread's contiguous share of an index range, for parallel regions that split work by hand
// (to vectorise over restrict-qualified arrays, or to gather per-thread lists that, joined in
// thread order, follow index order whatever the thread count).
#pragma once

#include <cstddef>

#include <omp.h>

namespace sph {

// Particles per chunk of the pair loops, which threads take as they come free: the cost of a
// particle varies with its class and neighbour count, and adaptive runs keep the costly L0
// particles together at the end of the arrays. Each particle's sums are its own, so the result
// does not depend on which thread takes which chunk.
inline constexpr int kPairLoopChunk = 256;

struct ThreadShare {
  std::size_t thread;  // omp_get_thread_num()
  std::size_t begin;   // [begin, end) of [0, n)
  std::size_t end;
};

// Inside a parallel region: the calling thread's share of [0, n); thread t's comes before t + 1's.
inline ThreadShare threadShare(std::size_t n) {
  const auto t = static_cast<std::size_t>(omp_get_thread_num());
  const auto team = static_cast<std::size_t>(omp_get_num_threads());
  return {t, n * t / team, n * (t + 1) / team};
}

}  // namespace sph
