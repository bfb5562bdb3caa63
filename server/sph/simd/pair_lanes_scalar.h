// The lane types the incompressible solvers' pair passes are written against (pair passes are
// templates on a Lanes type L, one source for every form; simd_level.h): here one lane, plain
// floats, the scalar form; pair_lanes_avx512.h has 16. A pass walks a particle's neighbour list
// L::kWidth entries at a time, with a mask of the live lanes.
//
//   L::F, L::I, L::M       float lanes, index lanes, a lane mask
//   set(x), zero()         a value in every lane
//   live(left)             the first min(left, width) lanes
//   loadIndex(p, m)        p[l] on the live lanes
//   load(p, m), store(p, m, v)  p[l] on the live lanes (0 on dead lanes), written on the live lanes
//   gather(m, j, base)     base[j_l] (0 on dead lanes)
//   gatherTriples(m, list, base, x, y, z)  base[3 j + 0, 1, 2] for j = list[l] (0 on dead lanes)
//   loadLevels(p, m)       the bytes p[l] as index lanes on the live lanes (0 on dead lanes)
//   L::T, table(p)         a table of 16 floats (AVX2 keeps the first 8)
//   lookup(t, k)           t[k_l], k_l < 8: a register permute, not a memory gather
//   le, lt, eq, neq        comparisons -> M; any(m); andMask(a, b)
//   select(m, a, b)        a where m, else b; maskz(m, a): a where m, else 0
//   max, min, sqrt; sum(v), minOf(v): over the lanes
//
// The vector types add index-lane operations for the partner search and the neighbour scan, whose
// scalar forms are their own sources (partner_search.cpp, neighbor_scan.cpp):
//
//   setIndex(x)              x in every index lane
//   gatherIndex(m, j, base)  base[j_l] as 32-bit integers (0 on dead lanes)
//   tripleIndex(j)           3 j, the gather index of a packed x, y, z triple
//   eqIndex, ltIndex         comparisons -> M (ltIndex unsigned, as ids and indices are)
//   selectIndex(m, a, b)     a where m, else b
//   minOfIndex(v)            the least lane, unsigned; laneOf(v, l): lane l
//   orMask(a, b); bits(m)    the union of masks; a mask as bits (bit l: lane l)
//   le(m, a, b), neqIndex(m, a, b)  the comparisons on the lanes of m only
//   fmadd(a, b, c)           a b + c, rounded once
//   compress(m, v)           the lanes of v in m, packed to the front in order
//   storeIndex(p, v)         all lanes of v to p[0 .. width)
//   kMaskedByteStore         whether the lanes store bytes under a mask; where they do (AVX-512):
//     storeBytes(p, m, v)    v_l (below 256) as the bytes p[l] on the live lanes; where not (AVX2):
//     loadIndex(p), gatherIndex(j, base), storeBytes(p, v)  the same on all lanes, no mask
//
// and, for the thesis stages:
//
//   none()                   no lanes; gt(a, b); eq(m, a, b), neq(m, a, b) on the lanes of m
//   andNotMask(a, b)         the lanes of b not in a
//   rsqrt(a)                 the estimate of 1 / sqrt(a) (AVX2 12 bits, AVX-512 14)
//   fmaddOn(m, a, b, c)      a b + c on the lanes of m, c elsewhere
//   addOn(m, a, b)           a + b on the lanes of m, a elsewhere
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace sph {

struct ScalarLanes {
  static constexpr int kWidth = 1;
  using F = float;
  using I = std::uint32_t;
  using M = bool;
  using T = const float*;

  static F set(float x) { return x; }
  static F zero() { return 0.0f; }
  static M live(std::uint32_t left) { return left > 0; }
  static I loadIndex(const std::uint32_t* p, M) { return *p; }
  static F load(const float* p, M) { return *p; }
  static void store(float* p, M, F v) { *p = v; }
  static F gather(M, I j, const float* base) { return base[j]; }
  static I loadLevels(const std::uint8_t* p, M) { return *p; }
  static T table(const float* p) { return p; }
  static F lookup(T t, I k) { return t[k]; }
  static void gatherTriples(M, const std::uint32_t* list, const float* base, F& x, F& y, F& z) {
    const float* t = base + 3 * static_cast<std::size_t>(*list);
    x = t[0];
    y = t[1];
    z = t[2];
  }
  static M le(F a, F b) { return a <= b; }
  static M lt(F a, F b) { return a < b; }
  static M eq(F a, F b) { return a == b; }
  static M neq(F a, F b) { return a != b; }
  static M andMask(M a, M b) { return a && b; }
  static bool any(M m) { return m; }
  static F select(M m, F a, F b) { return m ? a : b; }
  static F maskz(M m, F a) { return m ? a : 0.0f; }
  static F max(F a, F b) { return a < b ? b : a; }
  static F min(F a, F b) { return b < a ? b : a; }
  static F sqrt(F a) { return std::sqrt(a); }
  static float sum(F v) { return v; }
  static float minOf(F v) { return v; }
};

}  // namespace sph
