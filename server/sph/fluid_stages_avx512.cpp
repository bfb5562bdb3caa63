#include "sph/fluid_stages_avx512.h"

#ifdef SPH_AVX512_FLUID

// GCC 12's AVX-512 headers build _mm512_max_ps and the reductions on *_undefined_ps(), which its
// own flow analysis reports as maybe-uninitialized once inlined (GCC bug 105593).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <immintrin.h>

#include <cmath>
#include <limits>
#include <span>

#include "sph/coincident_pairs.h"
#include "sph/fluid_stage_ends.h"

namespace sph::avx512 {

namespace {

static_assert(sizeof(Vec3) == 3 * sizeof(float), "positions and velocities are gathered as packed floats");

// KernelConstants of one size class in all 16 lanes. The kernels clamp (h^2 - r^2) and (h - r) at
// zero instead of branching: a mixed pair may lie beyond the smaller support (eq. (3.34)), and
// there every kernel of that class is zero, as in the scalar forms of kernels.h.
struct LaneKernel {
  __m512 h, h2, poly6, poly6_grad, spiky_grad, visc_lap;

  explicit LaneKernel(const KernelConstants& k)
      : h(_mm512_set1_ps(k.h)),
        h2(_mm512_set1_ps(k.h2)),
        poly6(_mm512_set1_ps(k.poly6)),
        poly6_grad(_mm512_set1_ps(k.poly6_grad)),
        spiky_grad(_mm512_set1_ps(k.spiky_grad)),
        visc_lap(_mm512_set1_ps(k.visc_lap)) {}
};

// The kernel terms of one batch of pairs; the same fields the scalar force loop computes.
struct PairKernels {
  __m512 spiky, visc, cgrad, clap;
};

inline __m512 clampZero(__m512 v) { return _mm512_max_ps(v, _mm512_setzero_ps()); }

inline __m512 poly6(const LaneKernel& k, __m512 r2) {  // eq. (3.1)
  const __m512 d = clampZero(k.h2 - r2);
  return k.poly6 * d * d * d;
}

inline PairKernels forceKernels(const LaneKernel& k, __m512 r2, __m512 rl, __m512 inv_r) {
  const __m512 dr = clampZero(k.h - rl);
  const __m512 d2 = clampZero(k.h2 - r2);
  PairKernels out;
  out.spiky = k.spiky_grad * dr * dr * inv_r;                                  // eq. (3.4)
  out.visc = k.visc_lap * dr;                                                  // eq. (3.5)
  out.cgrad = k.poly6_grad * d2 * d2;                                          // eq. (3.2)
  out.clap = k.poly6_grad * d2 * (_mm512_set1_ps(3.0f) * k.h2 - _mm512_set1_ps(7.0f) * r2);  // (3.3)
  return out;
}

// Averaged kernel of eq. (3.35) on the lanes where the neighbour is of the other class.
inline __m512 average(__mmask16 mixed, __m512 own, __m512 other) {
  return _mm512_mask_mul_ps(own, mixed, _mm512_set1_ps(0.5f), own + other);
}

inline __mmask16 liveLanes(std::uint32_t left) {
  return left >= 16 ? __mmask16(0xFFFF) : __mmask16((1u << left) - 1u);
}

// base[idx[l]] on live lanes, 0 on the others.
inline __m512 gather(__mmask16 live, __m512i idx, const float* base) {
  return _mm512_mask_i32gather_ps(_mm512_setzero_ps(), live, idx, base, 4);
}

// Positions and velocities are packed x, y, z triples: the gather index is 3 j.
inline __m512i tripleIndex(__m512i idx) { return _mm512_add_epi32(idx, _mm512_add_epi32(idx, idx)); }

// 1 / |r| from r^2: the 14-bit estimate and one Newton step (about 1 ulp), 0 where r = 0 (the
// direction is undefined there, as in spikyGradFactor; such pairs get their pressure from
// coincidentPressureAcceleration instead).
inline __m512 inverseLength(__m512 r2) {
  const __m512 y = _mm512_rsqrt14_ps(r2);
  const __m512 refined = y * (_mm512_set1_ps(1.5f) - _mm512_set1_ps(0.5f) * r2 * y * y);
  return _mm512_maskz_mov_ps(_mm512_cmp_ps_mask(r2, _mm512_setzero_ps(), _CMP_GT_OQ), refined);
}

// A particle's position in all 16 lanes.
struct LaneCentre {
  __m512 x, y, z;
  LaneCentre(const float* pos, std::size_t i)
      : x(_mm512_set1_ps(pos[3 * i])), y(_mm512_set1_ps(pos[3 * i + 1])), z(_mm512_set1_ps(pos[3 * i + 2])) {}
};

// Neighbours b..b+15 of a list: which lanes are live, their indices, r = x_i - x_j and |r|^2.
struct PairBatch {
  __mmask16 live;
  __m512i j, j3;
  __m512 dx, dy, dz, r2;

  PairBatch(std::span<const std::uint32_t> list, std::uint32_t b, const LaneCentre& c, const float* pos)
      : live(liveLanes(static_cast<std::uint32_t>(list.size()) - b)),
        j(_mm512_maskz_loadu_epi32(live, list.data() + b)),
        j3(tripleIndex(j)),
        dx(c.x - gather(live, j3, pos)),
        dy(c.y - gather(live, j3, pos + 1)),
        dz(c.z - gather(live, j3, pos + 2)),
        r2(dx * dx + dy * dy + dz * dz) {}
};

// What both pair loops need to tell the size classes apart and evaluate their kernels.
class SizeClassLanes {
 public:
  SizeClassLanes(const SimParams& params, const KernelTable& kernels, const ParticleSet& p)
      : lanes_{LaneKernel(kernels[0]), LaneKernel(kernels[1])}, mass_(p.mass.data()) {
    // The attribute whose value tells the classes apart: the mass when their masses differ (the
    // loops gather it anyway, so spotting a mixed pair costs no extra gather), else the support
    // radius. Every particle of a class carries the class's mass and support.
    const auto classes = params.classes();
    const bool masses_differ = static_cast<float>(classes[0].mass) != static_cast<float>(classes[1].mass);
    key_ = masses_differ ? p.mass.data() : p.support.data();
  }

  // The kernels of particle i's class and of the other class, and i's key in every lane.
  const LaneKernel& own(int class_index) const { return lanes_[class_index]; }
  const LaneKernel& other(int class_index) const { return lanes_[1 - class_index]; }
  __m512 keyOf(std::size_t i) const { return _mm512_set1_ps(key_[i]); }

  // Lanes whose neighbour is of the other class than i; `mj` is the neighbours' gathered mass.
  __mmask16 mixed(const PairBatch& pair, __m512 mj, __m512 key_i) const {
    const __m512 key_j = key_ == mass_ ? mj : gather(pair.live, pair.j, key_);
    return _mm512_mask_cmp_ps_mask(pair.live, key_j, key_i, _CMP_NEQ_OQ);
  }

 private:
  LaneKernel lanes_[kSizeClassCount];
  const float* mass_;
  const float* key_;
};

}  // namespace

void computeDensityPressure(const SimParams& params, const KernelTable& kernels,
                            const NeighborGrid& grid, ParticleSet& p) {
  const float rho0 = static_cast<float>(params.rest_density);
  const float k = static_cast<float>(params.gas_stiffness);
  const SizeClassLanes classes(params, kernels, p);
  const float* pos = p.position.data()->data();
  const float* mass = p.mass.data();
  const std::size_t n = p.size();
#pragma omp parallel for schedule(dynamic, kPairLoopChunk)
  for (std::size_t i = 0; i < n; ++i) {
    const int ci = classIndex(p.size_class[i]);
    const LaneCentre centre(pos, i);
    const __m512 key_i = classes.keyOf(i);
    const auto list = grid.neighbors(i);
    __m512 sum = _mm512_setzero_ps();
    for (std::uint32_t b = 0; b < list.size(); b += 16) {
      const PairBatch pair(list, b, centre, pos);
      __m512 w = poly6(classes.own(ci), pair.r2);
      const __m512 mj = gather(pair.live, pair.j, mass);  // dead lanes: mass 0, so they add nothing
      const __mmask16 mixed = classes.mixed(pair, mj, key_i);
      if (mixed) w = average(mixed, w, poly6(classes.other(ci), pair.r2));
      sum = _mm512_fmadd_ps(mj, w, sum);  // eq. (3.11)
    }
    storeDensity(p, i, p.mass[i] * sph::poly6(kernels[ci], 0.0f) + _mm512_reduce_add_ps(sum), k, rho0);
  }
}

void computeAccelerations(const SimParams& params, const KernelTable& kernels,
                          const NeighborGrid& grid, ParticleSet& p, bool propagate_surface_distance) {
  const ForceConstants constants(params);
  const SizeClassLanes classes(params, kernels, p);
  const float* pos = p.position.data()->data();
  const float* vel = p.velocity.data()->data();
  const float* mass = p.mass.data();
  const float* volume = p.volume.data();
  const float* pressure_term = p.pressure_term.data();
  const float* surface_distance = p.surface_distance.data();
  const std::size_t n = p.size();

#pragma omp parallel for schedule(dynamic, kPairLoopChunk)
  for (std::size_t i = 0; i < n; ++i) {
    const int ci = classIndex(p.size_class[i]);
    const LaneCentre centre(pos, i);
    const __m512 uxi = _mm512_set1_ps(vel[3 * i]);
    const __m512 uyi = _mm512_set1_ps(vel[3 * i + 1]);
    const __m512 uzi = _mm512_set1_ps(vel[3 * i + 2]);
    const __m512 key_i = classes.keyOf(i);
    const __m512 pti = _mm512_set1_ps(pressure_term[i]);

    const __m512 zero = _mm512_setzero_ps();
    __m512 pax = zero, pay = zero, paz = zero;  // f_pressure / rho_i, negated at the end
    __m512 vx = zero, vy = zero, vz = zero;     // f_viscosity / mu
    __m512 nx = zero, ny = zero, nz = zero;     // n = grad c, eq. (3.17)
    __m512 lap = zero;                          // lap c, eq. (3.18), without the self term
    __m512 hop = _mm512_set1_ps(std::numeric_limits<float>::infinity());
    Vec3 contact_acc = Vec3::Zero();            // from neighbours on the same point

    const auto list = grid.neighbors(i);
    for (std::uint32_t b = 0; b < list.size(); b += 16) {
      const PairBatch pair(list, b, centre, pos);
      const __mmask16 live = pair.live;
      const __m512i j = pair.j;
      const __m512 dx = pair.dx, dy = pair.dy, dz = pair.dz, r2 = pair.r2;
      const __mmask16 coincident = _mm512_mask_cmp_ps_mask(live, r2, _mm512_setzero_ps(), _CMP_EQ_OQ);
      if (coincident) {  // rare: pairs on one point (coincident_pairs.h); 1/|r| = 0 zeroes their pressure lanes below
        for (std::uint32_t bits = coincident; bits != 0; bits &= bits - 1) {
          contact_acc += coincidentPressureAcceleration(p, kernels, i, list[b + static_cast<std::uint32_t>(__builtin_ctz(bits))]);
        }
      }
      const __m512 inv_r = inverseLength(r2);
      const __m512 rl = r2 * inv_r;
      PairKernels kern = forceKernels(classes.own(ci), r2, rl, inv_r);
      // Dead lanes gather mass and volume 0, so every term below is 0 there.
      const __m512 mj = gather(live, j, mass);
      const __m512 volj = gather(live, j, volume);
      const __mmask16 mixed = classes.mixed(pair, mj, key_i);
      if (mixed) {
        const PairKernels o = forceKernels(classes.other(ci), r2, rl, inv_r);
        kern = {average(mixed, kern.spiky, o.spiky), average(mixed, kern.visc, o.visc),
                average(mixed, kern.cgrad, o.cgrad), average(mixed, kern.clap, o.clap)};
      }
      // Pressure, eq. (3.13) divided by rho_i.
      const __m512 s = mj * (pti + gather(live, j, pressure_term)) * kern.spiky;
      pax = _mm512_fmadd_ps(s, dx, pax);
      pay = _mm512_fmadd_ps(s, dy, pay);
      paz = _mm512_fmadd_ps(s, dz, paz);
      // Viscosity, eq. (3.14).
      const __m512 sv = volj * kern.visc;
      vx = _mm512_fmadd_ps(sv, gather(live, pair.j3, vel) - uxi, vx);
      vy = _mm512_fmadd_ps(sv, gather(live, pair.j3, vel + 1) - uyi, vy);
      vz = _mm512_fmadd_ps(sv, gather(live, pair.j3, vel + 2) - uzi, vz);
      // Colour field gradient and Laplacian, eqs. (3.16)-(3.18).
      const __m512 sc = volj * kern.cgrad;
      nx = _mm512_fmadd_ps(sc, dx, nx);
      ny = _mm512_fmadd_ps(sc, dy, ny);
      nz = _mm512_fmadd_ps(sc, dz, nz);
      lap = _mm512_fmadd_ps(volj, kern.clap, lap);
      if (propagate_surface_distance) {
        hop = _mm512_mask_min_ps(hop, live, hop, gather(live, j, surface_distance) + rl);
      }
    }

    ForceSums sums;
    sums.pressure_acc =
        contact_acc - Vec3(_mm512_reduce_add_ps(pax), _mm512_reduce_add_ps(pay), _mm512_reduce_add_ps(paz));
    sums.viscous = Vec3(_mm512_reduce_add_ps(vx), _mm512_reduce_add_ps(vy), _mm512_reduce_add_ps(vz));
    sums.normal = Vec3(_mm512_reduce_add_ps(nx), _mm512_reduce_add_ps(ny), _mm512_reduce_add_ps(nz));
    // The colour field sums over every j including i (3.16); only the Laplacian has a self term.
    sums.colour_laplacian = p.volume[i] * sph::poly6Laplacian(kernels[ci], 0.0f) + _mm512_reduce_add_ps(lap);
    storeAcceleration(p, i, sums, constants);
    if (propagate_surface_distance) p.surface_hop[i] = _mm512_reduce_min_ps(hop);
  }
}

}  // namespace sph::avx512

#endif  // SPH_AVX512_FLUID
