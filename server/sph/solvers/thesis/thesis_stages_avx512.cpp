// AVX-512 forms of the two pair-sum stages of thesis_stages.h: 16 neighbours per instruction, the
// neighbour attributes gathered by index, batches running on from one particle's list into the
// next's. Each particle still sums its own neighbours in list order (lane sums, then one fixed
// horizontal reduction) and which lanes they take depends only on the lists' layout, so the
// result does not depend on the thread count.
#include <cmath>
#include <limits>

#include "sph/simd/avx512_lanes.h"
#include "sph/simd/avx512_target.h"
#include "sph/solvers/thesis/coincident_pairs.h"
#include "sph/solvers/thesis/thesis_stage_ends.h"
#include "sph/solvers/thesis/thesis_stages.h"

SPH_AVX512_BEGIN

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
  LaneKernel() = default;

  // a's constants, b's on the lanes of `m`.
  static LaneKernel blend(__mmask16 m, const LaneKernel& a, const LaneKernel& b) {
    LaneKernel out;
    out.h = _mm512_mask_blend_ps(m, a.h, b.h);
    out.h2 = _mm512_mask_blend_ps(m, a.h2, b.h2);
    out.poly6 = _mm512_mask_blend_ps(m, a.poly6, b.poly6);
    out.poly6_grad = _mm512_mask_blend_ps(m, a.poly6_grad, b.poly6_grad);
    out.spiky_grad = _mm512_mask_blend_ps(m, a.spiky_grad, b.spiky_grad);
    out.visc_lap = _mm512_mask_blend_ps(m, a.visc_lap, b.visc_lap);
    return out;
  }
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
  out.spiky = k.spiky_grad * dr * dr * inv_r;                                                // eq. (3.4)
  out.visc = k.visc_lap * dr;                                                                // eq. (3.5)
  out.cgrad = k.poly6_grad * d2 * d2;                                                        // eq. (3.2)
  out.clap = k.poly6_grad * d2 * (_mm512_set1_ps(3.0f) * k.h2 - _mm512_set1_ps(7.0f) * r2);  // (3.3)
  return out;
}

// Averaged kernel of eq. (3.35) on the lanes where the neighbour is of the other class.
inline __m512 average(__mmask16 mixed, __m512 own, __m512 other) {
  return _mm512_mask_mul_ps(own, mixed, _mm512_set1_ps(0.5f), own + other);
}

using lanes::gather;
using lanes::liveLanes;

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
  LaneCentre() = default;
  // a's position, b's on the lanes of `m`.
  static LaneCentre blend(__mmask16 m, const LaneCentre& a, const LaneCentre& b) {
    LaneCentre out;
    out.x = _mm512_mask_blend_ps(m, a.x, b.x);
    out.y = _mm512_mask_blend_ps(m, a.y, b.y);
    out.z = _mm512_mask_blend_ps(m, a.z, b.z);
    return out;
  }
};

// 16 neighbour entries: which lanes are live, the neighbours j (and where they are listed, for
// gatherTriples), r = x_i - x_j (x_i the lane owner's centre) and |r|^2.
struct PairBatch {
  __mmask16 live;
  __m512i j;
  const std::uint32_t* list;
  __m512 dx, dy, dz, r2;

  PairBatch(__mmask16 live_lanes, const std::uint32_t* indices, const LaneCentre& c, const float* pos)
      : live(live_lanes), j(_mm512_maskz_loadu_epi32(live, indices)), list(indices) {
    __m512 xj, yj, zj;
    lanes::gatherTriples(live, indices, pos, xj, yj, zj);
    dx = c.x - xj;
    dy = c.y - yj;
    dz = c.z - zj;
    r2 = dx * dx + dy * dy + dz * dz;
  }
};

// What both pair loops need to tell the size classes apart and evaluate their kernels.
class LevelLanes {
 public:
  LevelLanes(const SimParams& params, const KernelTable& kernels, const ParticleSet& p)
      : lanes_{LaneKernel(kernels[0]), LaneKernel(kernels[1])}, mass_(p.mass.data()) {
    // The attribute whose value tells the classes apart: the mass when their masses differ (the
    // loops gather it anyway, so spotting a mixed pair costs no extra gather), else the support
    // radius. Every particle of a class carries the class's mass and support.
    const auto classes = params.levelProps();
    const bool masses_differ = static_cast<float>(classes[0].mass) != static_cast<float>(classes[1].mass);
    key_ = masses_differ ? p.mass.data() : p.support.data();
  }

  // The kernels of particle i's class and of the other class, and i's key in every lane.
  const LaneKernel& own(int class_index) const { return lanes_[class_index]; }
  const LaneKernel& other(int class_index) const { return lanes_[1 - class_index]; }
  __m512 keyOf(std::size_t i) const { return _mm512_set1_ps(key_[i]); }

  // Lanes whose neighbour is of the other class than the lane's owner i; `mj` is the neighbours'
  // gathered mass.
  __mmask16 mixed(const PairBatch& pair, __m512 mj, __m512 key_i) const {
    const __m512 key_j = key_ == mass_ ? mj : gather(pair.live, pair.j, key_);
    return _mm512_mask_cmp_ps_mask(pair.live, key_j, key_i, _CMP_NEQ_OQ);
  }

 private:
  LaneKernel lanes_[kMaxLevels];
  const float* mass_;
  const float* key_;
};

// The own-class and other-class kernels of a batch's lane owners.
struct OwnerKernels {
  const LaneKernel* own;
  const LaneKernel* other;
};

// Kernels for a batch that crosses from particle a's list into b's: a's where both are of one
// class, else a lane-by-lane blend, kept here while the batch is summed.
class KernelBlend {
 public:
  OwnerKernels of(__mmask16 b_lanes, OwnerKernels a, OwnerKernels b) {
    if (a.own == b.own) return a;
    blended_[0] = LaneKernel::blend(b_lanes, *a.own, *b.own);
    blended_[1] = LaneKernel::blend(b_lanes, *a.other, *b.other);
    return {&blended_[0], &blended_[1]};
  }

 private:
  LaneKernel blended_[2];
};

// The lanes of one batch: which particle owns them. A batch holds the next 16 entries of a block's
// lists (NeighborGrid: particle i + 1's list starts where i's ends), so where particle a's list
// ends inside it, the rest of the batch takes the first entries of the next particle's, b.
struct BatchLanes {
  __mmask16 a;  // a's lanes (from lane 0)
  __mmask16 b;  // b's lanes (after a's), 0 in a batch of a alone
};

// Walks the lists of block `block` 16 entries at a time across particles. Batches of one list at
// a time leave the end of every list's last batch empty, which costs most where lists are short
// (the gaze method's; docs/performance.md). Here a list's last entries
// share their batch with the next particle's first ones. A batch never spans three lists (after a
// list shorter than the rest of the batch, the batch ends). `Stage` provides:
//   Owner owner(i)                           per-particle lane constants of particle i
//   Owner blend(BatchLanes, Owner a, Owner b) a's on a's lanes, b's on b's
//   void sum(Owner, BatchLanes, indices, a, b)  sums a batch; with lanes.b set it finishes a and
//                                            starts b's sums with b's lanes
//   void finish(i)                           particle i's list has ended at a batch's end (or is
//                                            empty): store its result, clear the sums
template <typename Stage>
void walkBlock(const NeighborGrid& grid, std::size_t block, std::size_t n, Stage& stage) {
  const std::size_t first = block * NeighborGrid::kBlockSize;
  const std::size_t last = std::min(n, first + NeighborGrid::kBlockSize);
  std::size_t a = first;
  const std::uint32_t* next = grid.neighbors(a).data();
  std::uint32_t left = grid.neighborCount(a);  // entries of a's list not yet summed
  typename Stage::Owner owner = stage.owner(a);
  for (;;) {
    if (left == 0) {
      stage.finish(a);
      if (++a == last) return;
      left = grid.neighborCount(a);
      owner = stage.owner(a);
    } else if (left >= 16 || a + 1 == last || grid.neighborCount(a + 1) == 0) {
      const std::uint32_t taken = std::min<std::uint32_t>(left, 16);
      stage.sum(owner, BatchLanes{liveLanes(taken), 0}, next, a, a);
      next += taken;
      left -= taken;
    } else {
      const std::size_t b = a + 1;
      const std::uint32_t in_b = std::min<std::uint32_t>(16 - left, grid.neighborCount(b));
      const BatchLanes lanes{liveLanes(left), static_cast<__mmask16>(liveLanes(left + in_b) & ~liveLanes(left))};
      const typename Stage::Owner owner_b = stage.owner(b);
      stage.sum(stage.blend(lanes, owner, owner_b), lanes, next, a, b);
      next += left + in_b;
      a = b;
      left = grid.neighborCount(b) - in_b;
      owner = owner_b;
    }
  }
}

// Density and pressure, eq. (3.11)-(3.12), as a walkBlock stage.
class DensityStage {
 public:
  struct Owner {
    LaneCentre centre;
    __m512 key;
    OwnerKernels kernels;
  };

  DensityStage(const SimParams& params, const KernelTable& kernels, const LevelLanes& classes, KernelBlend& blend,
               ParticleSet& p)
      : kernels_(kernels),
        classes_(classes),
        kernel_blend_(blend),
        p_(p),
        pos_(p.position.data()->data()),
        mass_(p.mass.data()),
        rho0_(static_cast<float>(params.rest_density)),
        stiffness_(static_cast<float>(params.gas_stiffness)) {}

  [[gnu::always_inline]] Owner owner(std::size_t i) const {
    const int ci = levelIndex(p_.level[i]);
    return {LaneCentre(pos_, i), classes_.keyOf(i), {&classes_.own(ci), &classes_.other(ci)}};
  }
  [[gnu::always_inline]] Owner blend(BatchLanes lanes, const Owner& a, const Owner& b) {
    return {LaneCentre::blend(lanes.b, a.centre, b.centre), _mm512_mask_blend_ps(lanes.b, a.key, b.key),
            kernel_blend_.of(lanes.b, a.kernels, b.kernels)};
  }

  [[gnu::always_inline]] void sum(const Owner& o, BatchLanes lanes, const std::uint32_t* indices, std::size_t a,
                                  [[maybe_unused]] std::size_t b) {
    const PairBatch pair(lanes.a | lanes.b, indices, o.centre, pos_);
    __m512 w = poly6(*o.kernels.own, pair.r2);
    const __m512 mj = gather(pair.live, pair.j, mass_);  // dead lanes: mass 0, so they add nothing
    const __mmask16 mixed = classes_.mixed(pair, mj, o.key);
    if (mixed) w = average(mixed, w, poly6(*o.kernels.other, pair.r2));
    sum_ = _mm512_mask3_fmadd_ps(mj, w, sum_, lanes.a);  // eq. (3.11)
    if (lanes.b) {
      finish(a);
      sum_ = _mm512_maskz_mul_ps(lanes.b, mj, w);
    }
  }

  [[gnu::always_inline]] void finish(std::size_t i) {
    const int ci = levelIndex(p_.level[i]);
    storeDensity(p_, i, p_.mass[i] * sph::poly6(kernels_[ci], 0.0f) + _mm512_reduce_add_ps(sum_), stiffness_, rho0_);
    sum_ = _mm512_setzero_ps();
  }

 private:
  const KernelTable& kernels_;
  const LevelLanes& classes_;
  KernelBlend& kernel_blend_;
  ParticleSet& p_;
  const float* pos_;
  const float* mass_;
  float rho0_, stiffness_;
  __m512 sum_ = _mm512_setzero_ps();
};

// Pressure, viscosity and surface tension, eqs. (3.13)-(3.19), as a walkBlock stage.
class ForceStage {
 public:
  struct Owner {
    LaneCentre centre;
    __m512 ux, uy, uz, pressure_term, key;
    OwnerKernels kernels;
  };

  ForceStage(const SimParams& params, const KernelTable& kernels, const LevelLanes& classes, KernelBlend& blend,
             ParticleSet& p, bool propagate_surface_distance)
      : constants_(params),
        kernels_(kernels),
        classes_(classes),
        kernel_blend_(blend),
        p_(p),
        pos_(p.position.data()->data()),
        vel_(p.velocity.data()->data()),
        mass_(p.mass.data()),
        volume_(p.volume.data()),
        pressure_term_(p.pressure_term.data()),
        surface_distance_(p.surface_distance.data()),
        propagate_(propagate_surface_distance) {
    clear();
  }

  [[gnu::always_inline]] Owner owner(std::size_t i) const {
    const int ci = levelIndex(p_.level[i]);
    return {LaneCentre(pos_, i),
            _mm512_set1_ps(vel_[3 * i]),
            _mm512_set1_ps(vel_[3 * i + 1]),
            _mm512_set1_ps(vel_[3 * i + 2]),
            _mm512_set1_ps(pressure_term_[i]),
            classes_.keyOf(i),
            {&classes_.own(ci), &classes_.other(ci)}};
  }
  [[gnu::always_inline]] Owner blend(BatchLanes lanes, const Owner& a, const Owner& b) {
    const auto mix = [&](__m512 x, __m512 y) { return _mm512_mask_blend_ps(lanes.b, x, y); };
    return {LaneCentre::blend(lanes.b, a.centre, b.centre),
            mix(a.ux, b.ux),
            mix(a.uy, b.uy),
            mix(a.uz, b.uz),
            mix(a.pressure_term, b.pressure_term),
            mix(a.key, b.key),
            kernel_blend_.of(lanes.b, a.kernels, b.kernels)};
  }

  [[gnu::always_inline]] void sum(const Owner& o, BatchLanes lanes, const std::uint32_t* indices, std::size_t a,
                                  std::size_t b) {
    const PairBatch pair(lanes.a | lanes.b, indices, o.centre, pos_);
    const __mmask16 live = pair.live;
    const __m512i j = pair.j;
    const __m512 r2 = pair.r2;
    const __mmask16 coincident = _mm512_mask_cmp_ps_mask(live, r2, _mm512_setzero_ps(), _CMP_EQ_OQ);
    const __m512 inv_r = inverseLength(r2);
    const __m512 rl = r2 * inv_r;
    PairKernels kern = forceKernels(*o.kernels.own, r2, rl, inv_r);
    // Dead lanes gather mass and volume 0, so every term below is 0 there.
    const __m512 mj = gather(live, j, mass_);
    const __m512 volj = gather(live, j, volume_);
    const __mmask16 mixed = classes_.mixed(pair, mj, o.key);
    if (mixed) {
      const PairKernels other = forceKernels(*o.kernels.other, r2, rl, inv_r);
      kern = {average(mixed, kern.spiky, other.spiky), average(mixed, kern.visc, other.visc),
              average(mixed, kern.cgrad, other.cgrad), average(mixed, kern.clap, other.clap)};
    }
    Terms t;
    t.dx = pair.dx;
    t.dy = pair.dy;
    t.dz = pair.dz;
    t.s = mj * (o.pressure_term + gather(live, j, pressure_term_)) * kern.spiky;  // (3.13) / rho_i
    t.sv = volj * kern.visc;                                                      // (3.14)
    __m512 vjx, vjy, vjz;
    lanes::gatherTriples(live, pair.list, vel_, vjx, vjy, vjz);
    t.dux = vjx - o.ux;
    t.duy = vjy - o.uy;
    t.duz = vjz - o.uz;
    t.sc = volj * kern.cgrad;  // (3.16)-(3.18)
    t.lap = volj * kern.clap;
    t.hop = propagate_ ? gather(live, j, surface_distance_) + rl : _mm512_setzero_ps();
    add(t, lanes.a);
    // Rare: pairs on one point (coincident_pairs.h); 1/|r| = 0 zeroes their pressure lanes above.
    addCoincident(a, coincident & lanes.a, indices);
    if (lanes.b) {
      finish(a);
      add(t, lanes.b);
      addCoincident(b, coincident & lanes.b, indices);
    }
  }

  [[gnu::always_inline]] void finish(std::size_t i) {
    const int ci = levelIndex(p_.level[i]);
    ForceSums sums;
    sums.pressure_acc =
        contact_ - Vec3(_mm512_reduce_add_ps(pax_), _mm512_reduce_add_ps(pay_), _mm512_reduce_add_ps(paz_));
    sums.viscous = Vec3(_mm512_reduce_add_ps(vx_), _mm512_reduce_add_ps(vy_), _mm512_reduce_add_ps(vz_));
    sums.normal = Vec3(_mm512_reduce_add_ps(nx_), _mm512_reduce_add_ps(ny_), _mm512_reduce_add_ps(nz_));
    // The colour field sums over every j including i (3.16); only the Laplacian has a self term.
    sums.colour_laplacian = p_.volume[i] * sph::poly6Laplacian(kernels_[ci], 0.0f) + _mm512_reduce_add_ps(lap_);
    storeAcceleration(p_, i, sums, constants_);
    if (propagate_) p_.surface_hop[i] = _mm512_reduce_min_ps(hop_);
    clear();
  }

 private:
  // One batch's per-lane terms, before they are summed into the lanes' owners.
  struct Terms {
    __m512 dx, dy, dz, s, sv, dux, duy, duz, sc, lap, hop;
  };

  [[gnu::always_inline]] void add(const Terms& t, __mmask16 lanes) {
    pax_ = _mm512_mask3_fmadd_ps(t.s, t.dx, pax_, lanes);
    pay_ = _mm512_mask3_fmadd_ps(t.s, t.dy, pay_, lanes);
    paz_ = _mm512_mask3_fmadd_ps(t.s, t.dz, paz_, lanes);
    vx_ = _mm512_mask3_fmadd_ps(t.sv, t.dux, vx_, lanes);
    vy_ = _mm512_mask3_fmadd_ps(t.sv, t.duy, vy_, lanes);
    vz_ = _mm512_mask3_fmadd_ps(t.sv, t.duz, vz_, lanes);
    nx_ = _mm512_mask3_fmadd_ps(t.sc, t.dx, nx_, lanes);
    ny_ = _mm512_mask3_fmadd_ps(t.sc, t.dy, ny_, lanes);
    nz_ = _mm512_mask3_fmadd_ps(t.sc, t.dz, nz_, lanes);
    lap_ = _mm512_mask_add_ps(lap_, lanes, lap_, t.lap);
    if (propagate_) hop_ = _mm512_mask_min_ps(hop_, lanes, hop_, t.hop);
  }

  void addCoincident(std::size_t i, __mmask16 lanes, const std::uint32_t* indices) {
    for (std::uint32_t bits = lanes; bits != 0; bits &= bits - 1) {
      contact_ += coincidentPressureAcceleration(p_, kernels_, i, indices[__builtin_ctz(bits)]);
    }
  }

  void clear() {
    const __m512 zero = _mm512_setzero_ps();
    pax_ = pay_ = paz_ = vx_ = vy_ = vz_ = nx_ = ny_ = nz_ = lap_ = zero;
    hop_ = _mm512_set1_ps(std::numeric_limits<float>::infinity());
    contact_ = Vec3::Zero();
  }

  const ForceConstants constants_;
  const KernelTable& kernels_;
  const LevelLanes& classes_;
  KernelBlend& kernel_blend_;
  ParticleSet& p_;
  const float *pos_, *vel_, *mass_, *volume_, *pressure_term_, *surface_distance_;
  const bool propagate_;
  __m512 pax_, pay_, paz_;  // f_pressure / rho_i, negated at the end
  __m512 vx_, vy_, vz_;     // f_viscosity / mu
  __m512 nx_, ny_, nz_;     // n = grad c, eq. (3.17)
  __m512 lap_;              // lap c, eq. (3.18), without the self term
  __m512 hop_;              // the surface distance's next hop
  Vec3 contact_;            // from neighbours on the same point
};

}  // namespace

#include "sph/solvers/thesis/bare_box_integration.inc"

// Each stage gets its LevelLanes (shared, read-only) and KernelBlend (its own scratch) from
// outside: a batch reads its kernel constants through pointers into them, and while they were
// members of the stage GCC could not tell those loads from the stage's own sums, so it kept the
// force loop's ten sums in memory and stored them after every batch (docs/performance.md).
void computeDensityPressure(const SimParams& params, const KernelTable& kernels, const NeighborGrid& grid,
                            ParticleSet& p) {
  const std::size_t n = p.size();
  const LevelLanes classes(params, kernels, p);
  // Blocks to whichever thread is free: the cost of a particle varies with its class and count.
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t block = 0; block < NeighborGrid::blockCount(n); ++block) {
    KernelBlend blend;
    DensityStage stage(params, kernels, classes, blend, p);
    walkBlock(grid, block, n, stage);
  }
}

void computeAccelerations(const SimParams& params, const KernelTable& kernels, const NeighborGrid& grid, ParticleSet& p,
                          bool propagate_surface_distance) {
  const std::size_t n = p.size();
  const LevelLanes classes(params, kernels, p);
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t block = 0; block < NeighborGrid::blockCount(n); ++block) {
    KernelBlend blend;
    ForceStage stage(params, kernels, classes, blend, p, propagate_surface_distance);
    walkBlock(grid, block, n, stage);
  }
}

ThesisStageForms thesisStageForms() { return {computeDensityPressure, computeAccelerations, integrateInBareBox}; }

}  // namespace sph::avx512

SPH_AVX512_END
