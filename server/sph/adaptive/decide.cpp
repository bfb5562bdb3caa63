#include "sph/adaptive/decide.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <omp.h>

namespace sph {

namespace {

// Distance from x to the nearest boundary the particle could touch: box faces, sphere and cylinder
// surfaces (the "boundaries" of (3.45), He et al. 2010).
float boundaryDistance(const Vec3& x, const BoxState& box, const Boundary& boundary) {
  float d = std::numeric_limits<float>::infinity();
  for (int a = 0; a < 3; ++a) d = std::min({d, x[a] - box.min[a], box.max[a] - x[a]});
  for (const Sphere& s : boundary.spheres) {
    const float dc = (x - s.centre.cast<float>()).norm() - static_cast<float>(s.radius);
    d = std::min(d, dc);
  }
  for (const Cylinder& c : boundary.cylinders) {
    const float dx = x.x() - static_cast<float>(c.x);
    const float dz = x.z() - static_cast<float>(c.z);
    d = std::min(d, std::sqrt(dx * dx + dz * dz) - static_cast<float>(c.radius));
  }
  return std::max(d, 0.0f);
}

}  // namespace

void decideBySurface(Simulation& sim, const AdaptiveConfig& config, std::span<std::int8_t> out) {
  ParticleSet& p = sim.particles();
  const NeighborGrid& grid = sim.grid();
  const std::size_t n = p.size();
  const float surface_threshold =
      static_cast<float>(config.surface_normal_scale * sim.params().surfaceThreshold());  // (3.44)
  const BoxState box = sim.boxNow();
  const Boundary& boundary = sim.scene().boundary;
  const float inf = std::numeric_limits<float>::infinity();

  // N_max is taken per size class: the classes have different neighbour counts by design (x_SMALL
  // 50, x_LARGE 20, table 3.2), and one global maximum would make every LARGE particle look
  // "isolated" next to SMALL ones, so splitting would creep inwards step after step.
  float max_pressure = 0.0f;
  float max_distance = 0.0f;
  std::uint32_t max_neighbors_small = 0;
  std::uint32_t max_neighbors_large = 0;
#pragma omp parallel for schedule(static) \
    reduction(max : max_pressure, max_distance, max_neighbors_small, max_neighbors_large)
  for (std::size_t i = 0; i < n; ++i) {
    float d = p.surface_hop[i];
    if (p.normal_length[i] >= surface_threshold) {
      d = 0.0f;  // a surface particle, (3.44)
    } else if (config.surface_includes_walls) {
      d = std::min(d, boundaryDistance(p.position[i], box, boundary));
    }
    p.surface_distance[i] = d;
    if (d < inf) max_distance = std::max(max_distance, d);
    max_pressure = std::max(max_pressure, p.pressure[i]);
    if (p.size_class[i] == SizeClass::Small) {
      max_neighbors_small = std::max(max_neighbors_small, grid.neighborCount(i));
    } else {
      max_neighbors_large = std::max(max_neighbors_large, grid.neighborCount(i));
    }
  }

  // Character field, eq. (3.45), and the decision, eq. (3.46). Particles the distance field has
  // not reached yet are deeper than every reached one: they take d = dmax.
  const float alpha = static_cast<float>(config.alpha);
  const float beta = static_cast<float>(config.beta);
  const float gamma = static_cast<float>(config.gamma);
  const float inv_weights = 1.0f / (alpha + beta + gamma);
  const auto inverse = [](float v) { return v > 0.0f ? 1.0f / v : 0.0f; };
  const float inv_dmax = inverse(max_distance);
  const float inv_fmax = inverse(max_pressure);
  const float inv_nmax[kSizeClassCount] = {inverse(static_cast<float>(max_neighbors_small)),
                                           inverse(static_cast<float>(max_neighbors_large))};
  const float split_below = static_cast<float>(config.threshold);
  const float merge_from = 2.0f * split_below;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const float d = std::min(p.surface_distance[i], max_distance);
    const float f = std::max(p.pressure[i], 0.0f);
    const float cf = (alpha * d * inv_dmax + beta * (1.0f - f * inv_fmax) +
                      gamma * static_cast<float>(grid.neighborCount(i)) *
                          inv_nmax[classIndex(p.size_class[i])]) *
                     inv_weights;
    out[i] = cf < split_below ? kSplit : (cf >= merge_from ? kMerge : kRemain);
  }
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
void decideGazeRange(const GazeCircle& shared, const float* __restrict xyz, const float* __restrict radius,
                     std::int8_t* __restrict out, std::size_t begin, std::size_t end, bool hybrid) {
  const GazeCircle gaze = shared;
  if (hybrid) {
    for (std::size_t i = begin; i < end; ++i) {
      const std::int8_t by_gaze = gaze.decide(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2], radius[i]);
      const std::int8_t by_surface = out[i];
      out[i] = (by_gaze == kSplit && by_surface == kSplit)   ? kSplit
               : (by_gaze == kMerge || by_surface == kMerge) ? kMerge
                                                             : kRemain;
    }
  } else {
    for (std::size_t i = begin; i < end; ++i) {
      out[i] = gaze.decide(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2], radius[i]);
    }
  }
}

}  // namespace

void decideByGaze(const ParticleSet& particles, const ScreenCamera& camera, double gaze_x,
                  double gaze_y, const AdaptiveConfig& config, bool hybrid,
                  std::span<std::int8_t> out) {
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
#pragma omp parallel
  {
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    const auto team = static_cast<std::size_t>(omp_get_num_threads());
    decideGazeRange(gaze, xyz, radius, out.data(), n * t / team, n * (t + 1) / team, hybrid);
  }
}

}  // namespace sph
