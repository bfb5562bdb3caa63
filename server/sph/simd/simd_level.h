// Which instruction set the library's vector loops run, chosen once at run time from the CPU.
//
// The pattern, the same for every pass family that has a vector form `foo`:
//   foo.h          struct FooForms (the passes, as function pointers); scalar::fooForms() and
//                  avx512::fooForms(); and sph::fooForms(), the forms this CPU runs
//   foo.inc        the passes written once against a Lanes type (pair_lanes_scalar.h,
//                  pair_lanes_avx512.h), where they are pair loops
//   foo.cpp        the scalar form (namespace sph::scalar) and sph::fooForms(), which is
//                  formsForThisCpu(scalar::fooForms, avx512::fooForms)
//   foo_avx512.cpp the AVX-512 form (namespace sph::avx512, between SPH_AVX512_BEGIN and
//                  SPH_AVX512_END, avx512_target.h)
// The thesis's two pair stages (solvers/thesis/thesis_stages_avx512.cpp) keep hand-written
// intrinsics: their 16-lane batches run on from one particle's list into the next's, which a
// per-particle pass on lanes does not express.
// The whole library is built for baseline x86-64, so one build runs on any x86-64 CPU and takes
// the AVX-512 forms where the CPU has them.
#pragma once

#include <string>

namespace sph {

enum class SimdLevel { kScalar, kAvx512 };

const char* simdLevelName(SimdLevel level);

// The level of this process: AVX-512 where the CPU has AVX-512 F, BW, DQ, VL and CD and the build
// has the AVX-512 forms (not with -DSPH_FORCE_SCALAR=ON), unless the environment says
// SPH_SIMD=scalar. Decided on the first call; the same for the rest of the process.
SimdLevel simdLevel();

// Whether this build on this CPU can run `level` (the tests run both forms side by side).
bool simdAvailable(SimdLevel level);

// simdLevel()'s rule on its inputs: `env` is SPH_SIMD's value or nullptr. Throws
// std::invalid_argument for a value other than "scalar", "avx512" or "auto"; "avx512" where it
// is not available falls back to scalar (a portable default, never a crash).
SimdLevel chooseSimdLevel(bool avx512_available, const char* env);

// The forms of a pass family that simdLevel() names: formsForThisCpu(scalar::fooForms, avx512::fooForms).
template <typename Forms>
Forms formsForThisCpu(Forms (*scalar_forms)(), Forms (*avx512_forms)()) {
  return simdLevel() == SimdLevel::kAvx512 ? avx512_forms() : scalar_forms();
}

}  // namespace sph
