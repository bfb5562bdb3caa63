// Which instruction set the library's vector loops run, chosen once at run time from the CPU.
//
// The pattern, the same for every pass family that has a vector form `foo`:
//   foo.h          struct FooForms (the passes, as function pointers); scalar::fooForms(),
//                  avx2::fooForms() and avx512::fooForms(); and sph::fooForms(), the forms this
//                  CPU runs
//   foo.inc        the passes written once against a Lanes type (pair_lanes_scalar.h,
//                  pair_lanes_avx2.h, pair_lanes_avx512.h), where they are pair loops
//   foo.cpp        the scalar form (namespace sph::scalar) and sph::fooForms(), which is
//                  formsForThisCpu(scalar::fooForms, avx2::fooForms, avx512::fooForms)
//   foo_avx2.cpp   the AVX2 + FMA form (namespace sph::avx2, between SPH_AVX2_BEGIN and
//                  SPH_AVX2_END, avx2_target.h)
//   foo_avx512.cpp the AVX-512 form (namespace sph::avx512, between SPH_AVX512_BEGIN and
//                  SPH_AVX512_END, avx512_target.h)
// The thesis's two pair stages (solvers/thesis/thesis_stages.inc), the neighbour scan
// (neighbor_scan.inc) and the merge-partner search (adaptive/partner_search.inc) are written once
// for the two vector forms only, and their scalar forms are sources of their own: the stages'
// batches run on from one particle's list into the next's, the scan compresses accepted lanes and
// the search reduces its lanes' bests at the end, none of which the one-lane loops need.
// The whole library is built for baseline x86-64, so one build runs on any x86-64 CPU and takes
// the best form the CPU has: AVX-512, else AVX2 + FMA, else scalar.
//
// Why hand-written lane types and not a portable library (Google Highway, xsimd): the pass
// families are already one source each, and the same pbf passes on a lane type over Highway 1.0
// (Debian's) ran clearly slower than on these at the same width, mostly for want of a portable
// load-and-transpose of the neighbours' position triples. Highway would give SSE4 and ARM64 NEON
// forms for free (not SVE: its sizeless vectors cannot sit in the passes' lane structs); its lane
// type and the figures are in benchmarks/simd_library and docs/performance.md ("Portable SIMD
// library"). AVX2 runs the thesis preset's step 2.4-2.9x and pbf's about 2x faster than scalar
// (docs/performance.md, "Vector forms").
#pragma once

#include <string>

namespace sph {

// In order of preference: a later level is chosen over an earlier one wherever both run.
enum class SimdLevel { kScalar, kAvx2, kAvx512 };

const char* simdLevelName(SimdLevel level);

// The level of this process: the best one available (simdAvailable) unless the environment's
// SPH_SIMD names a lower one. Decided on the first call; the same for the rest of the process.
SimdLevel simdLevel();

// Whether this build on this CPU can run `level` (the tests run every available form side by
// side): AVX-512 needs AVX-512 F, BW, DQ, VL and CD; AVX2 needs AVX2, FMA and POPCNT; neither
// with -DSPH_FORCE_SCALAR=ON.
bool simdAvailable(SimdLevel level);

// simdLevel()'s rule on its inputs: `best` is the best level available, `env` SPH_SIMD's value or
// nullptr. Throws std::invalid_argument for a value other than "scalar", "avx2", "avx512" or
// "auto"; a level above `best` falls back to `best` (a portable default, never a crash).
SimdLevel chooseSimdLevel(SimdLevel best, const char* env);

// The forms of a pass family that simdLevel() names:
// formsForThisCpu(scalar::fooForms, avx2::fooForms, avx512::fooForms).
template <typename Forms>
Forms formsForThisCpu(Forms (*scalar_forms)(), Forms (*avx2_forms)(), Forms (*avx512_forms)()) {
  switch (simdLevel()) {
    case SimdLevel::kAvx512:
      return avx512_forms();
    case SimdLevel::kAvx2:
      return avx2_forms();
    case SimdLevel::kScalar:
      break;
  }
  return scalar_forms();
}

}  // namespace sph
