// pbf_passes_hwy.h: pbf_passes.inc with L = HwyLanes, once per Highway target. Highway's
// foreach_target.h includes this file again for every target, each time between
// HWY_BEFORE_NAMESPACE and HWY_AFTER_NAMESPACE, which build the code there for that target (as
// SPH_AVX512_BEGIN does for the hand-written forms); the project's headers come first, so their
// inline functions stay baseline code.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pbf_passes_hwy.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// The line above must come first.
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <type_traits>

#include "pbf_passes_hwy.h"
#include "sph/collision.h"
#include "sph/solvers/pbf/pbf_passes.h"

HWY_BEFORE_NAMESPACE();
namespace sph::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// pair_lanes_scalar.h's interface over Highway's ops, every lane type's in one source: as many
// lanes as the target's widest float vector holds. Portable where the hand-written types are
// not: triples come from three gathers (AVX-512's load-and-transpose is x86 code), and a target
// with fewer lanes than levels looks its tables up by gather instead of a register permute.
struct HwyLanes {
  using D = hn::ScalableTag<float>;
  using DI = hn::RebindToSigned<D>;
  static constexpr int kWidth = static_cast<int>(hn::MaxLanes(D()));
  static constexpr bool kTableInRegister = kWidth >= kMaxLevels;
  using F = hn::Vec<D>;
  using I = hn::Vec<DI>;
  using M = hn::Mask<D>;
  using T = std::conditional_t<kTableInRegister, F, const float*>;

  static F set(float x) { return hn::Set(D(), x); }
  static F zero() { return hn::Zero(D()); }
  static M live(std::uint32_t left) { return hn::FirstN(D(), left); }
  static I loadIndex(const std::uint32_t* p, M m) {
    return loadLive(DI(), reinterpret_cast<const std::int32_t*>(p), m);
  }
  static F load(const float* p, M m) { return loadLive(D(), p, m); }
  // p[l] on the live lanes (the first ones), 0 on the others. Highway 1.0's MaskedLoad is an
  // aligned whole-vector load and a blend below AVX2, so there a batch that ends its list is
  // copied out first.
  template <class DT, class Elem>
  static hn::Vec<DT> loadLive(DT d, const Elem* p, M m) {
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX2
    return hn::MaskedLoad(hn::RebindMask(d, m), d, p);
#else
    const std::size_t n = hn::CountTrue(D(), m);
    if (n == static_cast<std::size_t>(kWidth)) return hn::LoadU(d, p);
    HWY_ALIGN Elem first[kWidth] = {};
    std::copy_n(p, n, first);
    return hn::Load(d, first);
#endif
  }
  static void store(float* p, M m, F v) { hn::BlendedStore(v, m, D(), p); }
  // Dead lanes hold index 0 (loadIndex), a valid element: Highway 1.0 has no masked gather.
  static F gather(M m, I j, const float* base) { return hn::IfThenElseZero(m, hn::GatherIndex(D(), base, j)); }
  // Reads kWidth bytes whatever the mask (NeighborGrid::neighborLevels keeps 16 readable).
  static I loadLevels(const std::uint8_t* p, M m) {
    const hn::Rebind<std::uint8_t, D> d8;
    return hn::IfThenElseZero(hn::RebindMask(DI(), m), hn::PromoteTo(DI(), hn::LoadU(d8, p)));
  }
  static T table(const float* p) { return tableOf<T>(p); }
  static F lookup(T t, I k) { return lookupIn<T>(t, k); }
  // Templates, so that only the branch of this target's T is built.
  template <class Table>
  static Table tableOf(const float* p) {
    if constexpr (std::is_pointer_v<Table>) {
      return p;
    } else {
      return hn::LoadU(D(), p);
    }
  }
  template <class Table>
  static F lookupIn(Table t, I k) {
    if constexpr (std::is_pointer_v<Table>) {
      return hn::GatherIndex(D(), t, k);
    } else {
      return hn::TableLookupLanes(t, hn::IndicesFromVec(D(), k));
    }
  }
  static void gatherTriples(M m, const std::uint32_t* list, const float* base, F& x, F& y, F& z) {
    const I j = loadIndex(list, m);
    const I at = hn::Add(j, hn::Add(j, j));
    x = hn::IfThenElseZero(m, hn::GatherIndex(D(), base, at));
    y = hn::IfThenElseZero(m, hn::GatherIndex(D(), base + 1, at));
    z = hn::IfThenElseZero(m, hn::GatherIndex(D(), base + 2, at));
  }
  static M le(F a, F b) { return hn::Le(a, b); }
  static M lt(F a, F b) { return hn::Lt(a, b); }
  static M eq(F a, F b) { return hn::Eq(a, b); }
  static M neq(F a, F b) { return hn::Ne(a, b); }
  static M andMask(M a, M b) { return hn::And(a, b); }
  static bool any(M m) { return !hn::AllFalse(D(), m); }
  static F select(M m, F a, F b) { return hn::IfThenElse(m, a, b); }
  static F maskz(M m, F a) { return hn::IfThenElseZero(m, a); }
  static F max(F a, F b) { return hn::Max(a, b); }
  static F min(F a, F b) { return hn::Min(a, b); }
  static F sqrt(F a) { return hn::Sqrt(a); }
  static float sum(F v) { return hn::GetLane(hn::SumOfLanes(D(), v)); }
  static float minOf(F v) { return hn::GetLane(hn::MinOfLanes(D(), v)); }
};

using Lanes = HwyLanes;
#include "sph/solvers/pbf/pbf_passes.inc"

}  // namespace sph::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace sph {
HWY_EXPORT(pbfPassForms);

namespace hwy_form {

std::vector<Target> targetsOnThisCpu() {
  std::vector<Target> out;
  [[maybe_unused]] const auto add = [&](std::int64_t target, PbfPassForms (*forms)()) {
    if ((hwy::SupportedTargets() & target) != 0) out.push_back({hwy::TargetName(target), forms()});
  };
#if HWY_TARGETS & HWY_AVX3
  add(HWY_AVX3, N_AVX3::pbfPassForms);
#endif
#if HWY_TARGETS & HWY_AVX2
  add(HWY_AVX2, N_AVX2::pbfPassForms);
#endif
#if HWY_TARGETS & HWY_SSE4
  add(HWY_SSE4, N_SSE4::pbfPassForms);
#endif
#if HWY_TARGETS & HWY_SSSE3
  add(HWY_SSSE3, N_SSSE3::pbfPassForms);
#endif
#if HWY_TARGETS & HWY_EMU128
  add(HWY_EMU128, N_EMU128::pbfPassForms);
#endif
#if HWY_TARGETS & HWY_SCALAR
  add(HWY_SCALAR, N_SCALAR::pbfPassForms);
#endif
  return out;
}

PbfPassForms dispatchedForms() { return HWY_DYNAMIC_DISPATCH(pbfPassForms)(); }

}  // namespace hwy_form
}  // namespace sph
#endif  // HWY_ONCE
