// AVX2 forms of the two pair-sum stages of thesis_stages.h: 8 neighbours per instruction, the
// neighbour attributes gathered by index, batches running on from one particle's list into the
// next's. Each particle still sums its own neighbours in list order (lane sums, then one fixed
// horizontal reduction) and which lanes they take depends only on the lists' layout, so the
// result does not depend on the thread count.
#include <cmath>
#include <limits>

#include "sph/simd/avx2_lanes.h"
#include "sph/simd/avx2_target.h"
#include "sph/solvers/thesis/coincident_pairs.h"
#include "sph/solvers/thesis/thesis_stage_ends.h"
#include "sph/solvers/thesis/thesis_stages.h"

SPH_AVX2_BEGIN

namespace sph::avx2 {

namespace {

static_assert(sizeof(Vec3) == 3 * sizeof(float), "positions and velocities are gathered as packed floats");

// a, with b on the lanes of `m` (AVX-512's mask_blend, here on a vector mask).
inline __m256 maskBlend(__m256 m, __m256 a, __m256 b) { return _mm256_blendv_ps(a, b, m); }

// KernelConstants of one size class in all 8 lanes. The kernels clamp (h^2 - r^2) and (h - r) at
// zero instead of branching: a mixed pair may lie beyond the smaller support (eq. (3.34)), and
// there every kernel of that class is zero, as in the scalar forms of kernels.h.
struct LaneKernel {
  __m256 h, h2, poly6, poly6_grad, spiky_grad, visc_lap;

  explicit LaneKernel(const KernelConstants& k)
      : h(_mm256_set1_ps(k.h)),
        h2(_mm256_set1_ps(k.h2)),
        poly6(_mm256_set1_ps(k.poly6)),
        poly6_grad(_mm256_set1_ps(k.poly6_grad)),
        spiky_grad(_mm256_set1_ps(k.spiky_grad)),
        visc_lap(_mm256_set1_ps(k.visc_lap)) {}
  LaneKernel() = default;

  // a's constants, b's on the lanes of `m`.
  static LaneKernel blend(__m256 m, const LaneKernel& a, const LaneKernel& b) {
    LaneKernel out;
    out.h = maskBlend(m, a.h, b.h);
    out.h2 = maskBlend(m, a.h2, b.h2);
    out.poly6 = maskBlend(m, a.poly6, b.poly6);
    out.poly6_grad = maskBlend(m, a.poly6_grad, b.poly6_grad);
    out.spiky_grad = maskBlend(m, a.spiky_grad, b.spiky_grad);
    out.visc_lap = maskBlend(m, a.visc_lap, b.visc_lap);
    return out;
  }
};

// The kernel terms of one batch of pairs; the same fields the scalar force loop computes.
struct PairKernels {
  __m256 spiky, visc, cgrad, clap;
};

inline __m256 clampZero(__m256 v) { return _mm256_max_ps(v, _mm256_setzero_ps()); }

inline __m256 poly6(const LaneKernel& k, __m256 r2) {  // eq. (3.1)
  const __m256 d = clampZero(k.h2 - r2);
  return k.poly6 * d * d * d;
}

inline PairKernels forceKernels(const LaneKernel& k, __m256 r2, __m256 rl, __m256 inv_r) {
  const __m256 dr = clampZero(k.h - rl);
  const __m256 d2 = clampZero(k.h2 - r2);
  PairKernels out;
  out.spiky = k.spiky_grad * dr * dr * inv_r;                                                // eq. (3.4)
  out.visc = k.visc_lap * dr;                                                                // eq. (3.5)
  out.cgrad = k.poly6_grad * d2 * d2;                                                        // eq. (3.2)
  out.clap = k.poly6_grad * d2 * (_mm256_set1_ps(3.0f) * k.h2 - _mm256_set1_ps(7.0f) * r2);  // (3.3)
  return out;
}

// Averaged kernel of eq. (3.35) on the lanes where the neighbour is of the other class.
inline __m256 average(__m256 mixed, __m256 own, __m256 other) {
  return maskBlend(mixed, own, _mm256_set1_ps(0.5f) * (own + other));
}

using lanes2::gather;
using lanes2::liveLanes;

// 1 / |r| from r^2: the 12-bit estimate and one Newton step (a few ulp), 0 where r = 0 (the
// direction is undefined there, as in spikyGradFactor; such pairs get their pressure from
// coincidentPressureAcceleration instead).
inline __m256 inverseLength(__m256 r2) {
  const __m256 y = _mm256_rsqrt_ps(r2);
  const __m256 refined = y * (_mm256_set1_ps(1.5f) - _mm256_set1_ps(0.5f) * r2 * y * y);
  return _mm256_and_ps(_mm256_cmp_ps(r2, _mm256_setzero_ps(), _CMP_GT_OQ), refined);
}

// A particle's position in all 8 lanes.
struct LaneCentre {
  __m256 x, y, z;
  LaneCentre(const float* pos, std::size_t i)
      : x(_mm256_set1_ps(pos[3 * i])), y(_mm256_set1_ps(pos[3 * i + 1])), z(_mm256_set1_ps(pos[3 * i + 2])) {}
  LaneCentre() = default;
  // a's position, b's on the lanes of `m`.
  static LaneCentre blend(__m256 m, const LaneCentre& a, const LaneCentre& b) {
    LaneCentre out;
    out.x = maskBlend(m, a.x, b.x);
    out.y = maskBlend(m, a.y, b.y);
    out.z = maskBlend(m, a.z, b.z);
    return out;
  }
};

// 8 neighbour entries: which lanes are live, the neighbours j (and where they are listed, for
// gatherTriples), r = x_i - x_j (x_i the lane owner's centre) and |r|^2.
struct PairBatch {
  __m256 live;
  __m256i j;
  const std::uint32_t* list;
  __m256 dx, dy, dz, r2;

  PairBatch(__m256 live_lanes, const std::uint32_t* indices, const LaneCentre& c, const float* pos)
      : live(live_lanes),
        j(_mm256_maskload_epi32(reinterpret_cast<const int*>(indices), _mm256_castps_si256(live))),
        list(indices) {
    __m256 xj, yj, zj;
    lanes2::gatherTriples(live, indices, pos, xj, yj, zj);
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
  __m256 keyOf(std::size_t i) const { return _mm256_set1_ps(key_[i]); }

  // Lanes whose neighbour is of the other class than the lane's owner i; `mj` is the neighbours'
  // gathered mass.
  __m256 mixed(const PairBatch& pair, __m256 mj, __m256 key_i) const {
    const __m256 key_j = key_ == mass_ ? mj : gather(pair.live, pair.j, key_);
    return _mm256_and_ps(pair.live, _mm256_cmp_ps(key_j, key_i, _CMP_NEQ_OQ));
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
  OwnerKernels of(__m256 b_lanes, OwnerKernels a, OwnerKernels b) {
    if (a.own == b.own) return a;
    blended_[0] = LaneKernel::blend(b_lanes, *a.own, *b.own);
    blended_[1] = LaneKernel::blend(b_lanes, *a.other, *b.other);
    return {&blended_[0], &blended_[1]};
  }

 private:
  LaneKernel blended_[2];
};

// The lanes of one batch: which particle owns them. A batch holds the next 8 entries of a block's
// lists (NeighborGrid: particle i + 1's list starts where i's ends), so where particle a's list
// ends inside it, the rest of the batch takes the first entries of the next particle's, b.
struct BatchLanes {
  __m256 a;    // a's lanes (from lane 0)
  __m256 b;    // b's lanes (after a's), none in a batch of a alone
  bool has_b;  // whether b has lanes
};

// Walks the lists of block `block` 8 entries at a time across particles. Batches of one list at
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
    } else if (left >= 8 || a + 1 == last || grid.neighborCount(a + 1) == 0) {
      const std::uint32_t taken = std::min<std::uint32_t>(left, 8);
      stage.sum(owner, BatchLanes{liveLanes(taken), _mm256_setzero_ps(), false}, next, a, a);
      next += taken;
      left -= taken;
    } else {
      const std::size_t b = a + 1;
      const std::uint32_t in_b = std::min<std::uint32_t>(8 - left, grid.neighborCount(b));
      const BatchLanes lanes{liveLanes(left), _mm256_andnot_ps(liveLanes(left), liveLanes(left + in_b)), true};
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
    __m256 key;
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
    return {LaneCentre::blend(lanes.b, a.centre, b.centre), maskBlend(lanes.b, a.key, b.key),
            kernel_blend_.of(lanes.b, a.kernels, b.kernels)};
  }

  [[gnu::always_inline]] void sum(const Owner& o, BatchLanes lanes, const std::uint32_t* indices, std::size_t a,
                                  [[maybe_unused]] std::size_t b) {
    const PairBatch pair(_mm256_or_ps(lanes.a, lanes.b), indices, o.centre, pos_);
    __m256 w = poly6(*o.kernels.own, pair.r2);
    const __m256 mj = gather(pair.live, pair.j, mass_);  // dead lanes: mass 0, so they add nothing
    const __m256 mixed = classes_.mixed(pair, mj, o.key);
    if (_mm256_movemask_ps(mixed) != 0) w = average(mixed, w, poly6(*o.kernels.other, pair.r2));
    sum_ = _mm256_fmadd_ps(_mm256_and_ps(lanes.a, mj), w, sum_);  // eq. (3.11)
    if (lanes.has_b) {
      finish(a);
      sum_ = _mm256_and_ps(lanes.b, mj * w);
    }
  }

  [[gnu::always_inline]] void finish(std::size_t i) {
    const int ci = levelIndex(p_.level[i]);
    storeDensity(p_, i, p_.mass[i] * sph::poly6(kernels_[ci], 0.0f) + lanes2::sum(sum_), stiffness_, rho0_);
    sum_ = _mm256_setzero_ps();
  }

 private:
  const KernelTable& kernels_;
  const LevelLanes& classes_;
  KernelBlend& kernel_blend_;
  ParticleSet& p_;
  const float* pos_;
  const float* mass_;
  float rho0_, stiffness_;
  __m256 sum_ = _mm256_setzero_ps();
};

// Pressure, viscosity and surface tension, eqs. (3.13)-(3.19), as a walkBlock stage.
class ForceStage {
 public:
  struct Owner {
    LaneCentre centre;
    __m256 ux, uy, uz, pressure_term, key;
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
            _mm256_set1_ps(vel_[3 * i]),
            _mm256_set1_ps(vel_[3 * i + 1]),
            _mm256_set1_ps(vel_[3 * i + 2]),
            _mm256_set1_ps(pressure_term_[i]),
            classes_.keyOf(i),
            {&classes_.own(ci), &classes_.other(ci)}};
  }
  [[gnu::always_inline]] Owner blend(BatchLanes lanes, const Owner& a, const Owner& b) {
    const auto mix = [&](__m256 x, __m256 y) { return maskBlend(lanes.b, x, y); };
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
    const PairBatch pair(_mm256_or_ps(lanes.a, lanes.b), indices, o.centre, pos_);
    const __m256 live = pair.live;
    const __m256i j = pair.j;
    const __m256 r2 = pair.r2;
    const __m256 coincident = _mm256_and_ps(live, _mm256_cmp_ps(r2, _mm256_setzero_ps(), _CMP_EQ_OQ));
    const __m256 inv_r = inverseLength(r2);
    const __m256 rl = r2 * inv_r;
    PairKernels kern = forceKernels(*o.kernels.own, r2, rl, inv_r);
    // Dead lanes gather mass and volume 0, so every term below is 0 there.
    const __m256 mj = gather(live, j, mass_);
    const __m256 volj = gather(live, j, volume_);
    const __m256 mixed = classes_.mixed(pair, mj, o.key);
    if (_mm256_movemask_ps(mixed) != 0) {
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
    __m256 vjx, vjy, vjz;
    lanes2::gatherTriples(live, pair.list, vel_, vjx, vjy, vjz);
    t.dux = vjx - o.ux;
    t.duy = vjy - o.uy;
    t.duz = vjz - o.uz;
    t.sc = volj * kern.cgrad;  // (3.16)-(3.18)
    t.lap = volj * kern.clap;
    t.hop = propagate_ ? gather(live, j, surface_distance_) + rl : _mm256_setzero_ps();
    add(t, lanes.a);
    // Rare: pairs on one point (coincident_pairs.h); 1/|r| = 0 zeroes their pressure lanes above.
    addCoincident(a, lanes2::bitsOf(_mm256_and_ps(coincident, lanes.a)), indices);
    if (lanes.has_b) {
      finish(a);
      add(t, lanes.b);
      addCoincident(b, lanes2::bitsOf(_mm256_and_ps(coincident, lanes.b)), indices);
    }
  }

  [[gnu::always_inline]] void finish(std::size_t i) {
    const int ci = levelIndex(p_.level[i]);
    ForceSums sums;
    sums.pressure_acc = contact_ - Vec3(lanes2::sum(pax_), lanes2::sum(pay_), lanes2::sum(paz_));
    sums.viscous = Vec3(lanes2::sum(vx_), lanes2::sum(vy_), lanes2::sum(vz_));
    sums.normal = Vec3(lanes2::sum(nx_), lanes2::sum(ny_), lanes2::sum(nz_));
    // The colour field sums over every j including i (3.16); only the Laplacian has a self term.
    sums.colour_laplacian = p_.volume[i] * sph::poly6Laplacian(kernels_[ci], 0.0f) + lanes2::sum(lap_);
    storeAcceleration(p_, i, sums, constants_);
    if (propagate_) p_.surface_hop[i] = lanes2::minOf(hop_);
    clear();
  }

 private:
  // One batch's per-lane terms, before they are summed into the lanes' owners.
  struct Terms {
    __m256 dx, dy, dz, s, sv, dux, duy, duz, sc, lap, hop;
  };

  // The factors are zeroed off `lanes` (AVX2 has no masked FMA): a product with a zero factor adds
  // +0, so the other lanes' sums stay as they are, as AVX-512's masked forms leave them.
  [[gnu::always_inline]] void add(const Terms& t, __m256 lanes) {
    const __m256 s = _mm256_and_ps(lanes, t.s);
    const __m256 sv = _mm256_and_ps(lanes, t.sv);
    const __m256 sc = _mm256_and_ps(lanes, t.sc);
    pax_ = _mm256_fmadd_ps(s, t.dx, pax_);
    pay_ = _mm256_fmadd_ps(s, t.dy, pay_);
    paz_ = _mm256_fmadd_ps(s, t.dz, paz_);
    vx_ = _mm256_fmadd_ps(sv, t.dux, vx_);
    vy_ = _mm256_fmadd_ps(sv, t.duy, vy_);
    vz_ = _mm256_fmadd_ps(sv, t.duz, vz_);
    nx_ = _mm256_fmadd_ps(sc, t.dx, nx_);
    ny_ = _mm256_fmadd_ps(sc, t.dy, ny_);
    nz_ = _mm256_fmadd_ps(sc, t.dz, nz_);
    lap_ = lap_ + _mm256_and_ps(lanes, t.lap);
    if (propagate_) hop_ = maskBlend(lanes, hop_, _mm256_min_ps(hop_, t.hop));
  }

  void addCoincident(std::size_t i, std::uint32_t lanes, const std::uint32_t* indices) {
    for (std::uint32_t bits = lanes; bits != 0; bits &= bits - 1) {
      contact_ += coincidentPressureAcceleration(p_, kernels_, i, indices[__builtin_ctz(bits)]);
    }
  }

  void clear() {
    const __m256 zero = _mm256_setzero_ps();
    pax_ = pay_ = paz_ = vx_ = vy_ = vz_ = nx_ = ny_ = nz_ = lap_ = zero;
    hop_ = _mm256_set1_ps(std::numeric_limits<float>::infinity());
    contact_ = Vec3::Zero();
  }

  const ForceConstants constants_;
  const KernelTable& kernels_;
  const LevelLanes& classes_;
  KernelBlend& kernel_blend_;
  ParticleSet& p_;
  const float *pos_, *vel_, *mass_, *volume_, *pressure_term_, *surface_distance_;
  const bool propagate_;
  __m256 pax_, pay_, paz_;  // f_pressure / rho_i, negated at the end
  __m256 vx_, vy_, vz_;     // f_viscosity / mu
  __m256 nx_, ny_, nz_;     // n = grad c, eq. (3.17)
  __m256 lap_;              // lap c, eq. (3.18), without the self term
  __m256 hop_;              // the surface distance's next hop
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

}  // namespace sph::avx2

SPH_AVX2_END
