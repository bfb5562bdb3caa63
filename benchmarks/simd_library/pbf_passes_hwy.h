// The pbf pair passes (pbf_passes.inc) on a lane type written once over Google Highway, built by
// Highway for each of its x86 targets (SSSE3, SSE4, AVX2, AVX-512, and its 128-bit emulation):
// the candidate the "Portable SIMD library" measurement (docs/performance.md) sets against the
// hand-written lane types. Benchmark code only: the library does not use it.
#pragma once

#include <vector>

#include "sph/solvers/pbf/pbf_passes.h"

namespace sph::hwy_form {

struct Target {
  const char* name;  // Highway's name of the target: "AVX3" is its AVX-512
  PbfPassForms forms;
};

// The targets this build holds that this CPU runs, best first.
std::vector<Target> targetsOnThisCpu();

// The forms Highway's own run-time dispatch picks (HWY_DYNAMIC_DISPATCH).
PbfPassForms dispatchedForms();

}  // namespace sph::hwy_form
