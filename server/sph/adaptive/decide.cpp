#include "sph/adaptive/decide.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sph/thread_share.h"

namespace sph {

namespace {

// Distance from x to the nearest obstacle surface: spheres and cylinders (with the box faces, the
// "boundaries" of (3.45), He et al. 2010). Infinite when there are none.
float obstacleDistance(const Vec3& x, const Boundary& boundary) {
  float d = std::numeric_limits<float>::infinity();
  for (const Sphere& s : boundary.spheres) {
    const float dc = (x - s.centre.cast<float>()).norm() - static_cast<float>(s.radius);
    d = std::min(d, dc);
  }
  for (const Cylinder& c : boundary.cylinders) {
    const float dx = x.x() - static_cast<float>(c.x);
    const float dz = x.z() - static_cast<float>(c.z);
    d = std::min(d, std::sqrt(dx * dx + dz * dz) - static_cast<float>(c.radius));
  }
  return d;
}

// What the second pass of decideBySurface needs from the first: the maxima of (3.45).
struct FieldMaxima {
  float pressure = 0.0f;
  float distance = 0.0f;
  std::uint32_t neighbors[kSizeClassCount] = {0, 0};
};

// The arrays of the surface decision, restrict-qualified: the flags are bytes, which may otherwise
// alias anything, and GCC would not vectorise the passes.
struct SurfaceArrays {
  const float* __restrict xyz;  // packed x, y, z
  const float* __restrict hop;
  const float* __restrict normal_length;
  const float* __restrict pressure;
  const SizeClass* __restrict size_class;
  const std::uint32_t* __restrict neighbors;
  float* __restrict distance;  // surface_distance, written by the first pass
  std::int8_t* __restrict out;
};

// std::min and std::max by value, with their comparisons (so the same results, NaN included):
// GCC 12 does not vectorise an omp simd max reduction written with std::max, which returns a
// reference (the loop compiled to scalar code, 8 ns a particle on large_box).
inline float minOf(float a, float b) { return b < a ? b : a; }
inline float maxOf(float a, float b) { return a < b ? b : a; }
inline std::uint32_t maxOf(std::uint32_t a, std::uint32_t b) { return a < b ? b : a; }

// First pass over [begin, end): d_i (0 on the surface, (3.44); else the smaller of this step's
// hop and, with walls, the boundary distance) and the maxima. Obstacles (a loop over spheres and
// cylinders) are a template switch, so the common case of a bare box vectorises.
template <bool kObstacles>
FieldMaxima surfaceDistances(const SurfaceArrays& arrays, std::size_t begin, std::size_t end, float surface_threshold,
                             bool include_walls, const BoxState& box, const Boundary& boundary) {
  // A local copy: read through the reference, the loop did not vectorise either.
  const SurfaceArrays a = arrays;
  const float inf = std::numeric_limits<float>::infinity();
  // Plain scalars for the maxima: GCC vectorises no reduction into a struct member.
  float max_distance = 0.0f, max_pressure = 0.0f;
  std::uint32_t max_small = 0, max_large = 0;
  // Float max reductions vectorise only where the order may change (exact for max): omp simd.
#pragma omp simd reduction(max : max_distance, max_pressure, max_small, max_large)
  for (std::size_t i = begin; i < end; ++i) {
    const float x = a.xyz[3 * i], y = a.xyz[3 * i + 1], z = a.xyz[3 * i + 2];
    float wall = minOf(minOf(minOf(x - box.min.x(), box.max.x() - x), minOf(y - box.min.y(), box.max.y() - y)),
                       minOf(z - box.min.z(), box.max.z() - z));
    if constexpr (kObstacles) wall = minOf(wall, obstacleDistance(Vec3(x, y, z), boundary));
    const float hop = a.hop[i];
    float d = include_walls ? minOf(hop, maxOf(wall, 0.0f)) : hop;
    d = a.normal_length[i] >= surface_threshold ? 0.0f : d;
    a.distance[i] = d;
    max_distance = maxOf(max_distance, d < inf ? d : 0.0f);
    max_pressure = maxOf(max_pressure, a.pressure[i]);
    const std::uint32_t count = a.neighbors[i];
    const bool small = a.size_class[i] == SizeClass::Small;
    max_small = maxOf(max_small, small ? count : 0u);
    max_large = maxOf(max_large, small ? 0u : count);
  }
  FieldMaxima m;
  m.distance = max_distance;
  m.pressure = max_pressure;
  m.neighbors[0] = max_small;
  m.neighbors[1] = max_large;
  return m;
}

}  // namespace

DecisionCounts decideBySurface(Simulation& sim, const AdaptiveConfig& config, std::span<std::int8_t> out) {
  ParticleSet& p = sim.particles();
  const std::size_t n = p.size();
  const float surface_threshold =
      static_cast<float>(config.surface_normal_scale * sim.params().surfaceThreshold());  // (3.44)
  const BoxState box = sim.boxNow();
  const Boundary& boundary = sim.scene().boundary;
  const bool obstacles = !boundary.spheres.empty() || !boundary.cylinders.empty();
  const SurfaceArrays arrays{p.position.data()->data(), p.surface_hop.data(),
                             p.normal_length.data(),    p.pressure.data(),
                             p.size_class.data(),       sim.grid().neighborCounts().data(),
                             p.surface_distance.data(), out.data()};

  // Character field, eq. (3.45), and the decision, eq. (3.46). N_max is taken per size class: the
  // classes have different neighbour counts by design (x_SMALL 50, x_LARGE 20, table 3.2), and one
  // global maximum would make every LARGE particle look "isolated" next to SMALL ones, so splitting
  // would creep inwards step after step. Particles the distance field has not reached yet are
  // deeper than every reached one: they take d = dmax.
  const float alpha = static_cast<float>(config.alpha);
  const float beta = static_cast<float>(config.beta);
  const float gamma = static_cast<float>(config.gamma);
  const float inv_weights = 1.0f / (alpha + beta + gamma);
  const auto inverse = [](float v) { return v > 0.0f ? 1.0f / v : 0.0f; };
  const float split_below = static_cast<float>(config.threshold);
  const float merge_from = 2.0f * split_below;

  FieldMaxima all;
  int split_wanted = 0;
  int merge_wanted = 0;
  // One parallel region, two passes: the maxima (combined in any order, max is exact) between.
#pragma omp parallel reduction(+ : split_wanted, merge_wanted)
  {
    const ThreadShare share = threadShare(n);
    const std::size_t begin = share.begin;
    const std::size_t end = share.end;
    const FieldMaxima mine = obstacles ? surfaceDistances<true>(arrays, begin, end, surface_threshold,
                                                                config.surface_includes_walls, box, boundary)
                                       : surfaceDistances<false>(arrays, begin, end, surface_threshold,
                                                                 config.surface_includes_walls, box, boundary);
#pragma omp critical(sph_surface_maxima)
    {
      all.pressure = std::max(all.pressure, mine.pressure);
      all.distance = std::max(all.distance, mine.distance);
      for (int c = 0; c < kSizeClassCount; ++c) all.neighbors[c] = std::max(all.neighbors[c], mine.neighbors[c]);
    }
#pragma omp barrier
    const float max_distance = all.distance;
    const float inv_dmax = inverse(all.distance);
    const float inv_fmax = inverse(all.pressure);
    const float inv_nmax[kSizeClassCount] = {inverse(static_cast<float>(all.neighbors[0])),
                                             inverse(static_cast<float>(all.neighbors[1]))};
    const SurfaceArrays a = arrays;
    for (std::size_t i = begin; i < end; ++i) {
      const float d = std::min(a.distance[i], max_distance);
      const float f = std::max(a.pressure[i], 0.0f);
      const int large = classIndex(a.size_class[i]);  // 0 SMALL, 1 LARGE
      const float cf = (alpha * d * inv_dmax + beta * (1.0f - f * inv_fmax) +
                        gamma * static_cast<float>(a.neighbors[i]) * inv_nmax[large]) *
                       inv_weights;
      const int split = cf < split_below;
      const int merge = cf >= merge_from;
      a.out[i] = static_cast<std::int8_t>(split * kSplit + merge * kMerge);  // both cannot hold
      split_wanted += split & large;
      merge_wanted += merge & (1 - large);
    }
  }
  return {split_wanted, merge_wanted};
}

namespace {

// eq. (3.47)-(3.48) for one particle, with the hysteresis ring. Distances are in units of the
// viewport width (y is a fraction of the height).
struct GazeCircle {
  FastProjection projection;
  float x, y, inv_aspect, inner_radius, outer_radius;

  std::int8_t decide(float px, float py, float pz, float radius) const {
    const FastScreenDisc disc = projection.project(px, py, pz, radius);
    const float dx = disc.x - x;
    const float dy = (disc.y - y) * inv_aspect;
    const float dist2 = dx * dx + dy * dy;
    const float inner = inner_radius + disc.radius;
    const float outer = outer_radius + disc.radius;
    // f = sgn(|r_i - r_gaze|^2 - (r_i + r_gaze)^2); SPLIT where f < 0. Behind the eye: MERGE.
    const int split = disc.in_front & (dist2 < inner * inner);
    const int merge = !disc.in_front | (dist2 > outer * outer);
    // Arithmetic rather than a conditional: a split wins, and the ring (neither) is kRemain = 0.
    return static_cast<std::int8_t>(split * kSplit + (1 - split) * merge * kMerge);
  }
};

// Particles [begin, end): single precision, no branches and restrict-qualified arrays (the
// decisions are bytes, which may otherwise alias anything), so that GCC vectorises the loop.
DecisionCounts decideGazeRange(const GazeCircle& shared, const float* __restrict xyz, const float* __restrict radius,
                               const SizeClass* __restrict size_class, std::int8_t* __restrict out, std::size_t begin,
                               std::size_t end, bool hybrid) {
  const GazeCircle gaze = shared;
  int split_wanted = 0;
  int merge_wanted = 0;
  const auto count = [&](std::int8_t decision, SizeClass c) {
    const int large = classIndex(c);  // 0 SMALL, 1 LARGE
    split_wanted += (decision == kSplit) & large;
    merge_wanted += (decision == kMerge) & (1 - large);
  };
  if (hybrid) {
    for (std::size_t i = begin; i < end; ++i) {
      const std::int8_t by_gaze = gaze.decide(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2], radius[i]);
      const std::int8_t by_surface = out[i];
      out[i] = (by_gaze == kSplit && by_surface == kSplit)   ? kSplit
               : (by_gaze == kMerge || by_surface == kMerge) ? kMerge
                                                             : kRemain;
      count(out[i], size_class[i]);
    }
  } else {
    for (std::size_t i = begin; i < end; ++i) {
      out[i] = gaze.decide(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2], radius[i]);
      count(out[i], size_class[i]);
    }
  }
  return {split_wanted, merge_wanted};
}

}  // namespace

DecisionCounts decideByGaze(const ParticleSet& particles, const ScreenCamera& camera, double gaze_x, double gaze_y,
                            const AdaptiveConfig& config, bool hybrid, std::span<std::int8_t> out) {
  const Projector projector(camera);
  const GazeCircle gaze{projector.fast(),
                        static_cast<float>(gaze_x),
                        static_cast<float>(gaze_y),
                        static_cast<float>(1.0 / projector.aspect()),
                        static_cast<float>(config.gaze_radius),
                        static_cast<float>(config.gaze_ring_radius)};
  const float* xyz = particles.position.data()->data();  // packed x, y, z
  const float* radius = particles.radius.data();
  const std::size_t n = particles.size();
  int split_wanted = 0;
  int merge_wanted = 0;
#pragma omp parallel reduction(+ : split_wanted, merge_wanted)
  {
    const ThreadShare share = threadShare(n);
    const DecisionCounts mine =
        decideGazeRange(gaze, xyz, radius, particles.size_class.data(), out.data(), share.begin, share.end, hybrid);
    split_wanted += mine.split_wanted;
    merge_wanted += mine.merge_wanted;
  }
  return {split_wanted, merge_wanted};
}

}  // namespace sph
