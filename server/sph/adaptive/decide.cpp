#include "sph/adaptive/decide.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

void decideBySurface(const Simulation& sim, const AdaptiveConfig& config,
                     std::vector<float>& distance, std::vector<float>& scratch,
                     std::span<std::int8_t> out) {
  const ParticleSet& p = sim.particles();
  const NeighborGrid& grid = sim.grid();
  const std::size_t n = p.size();
  const float surface_threshold =
      static_cast<float>(config.surface_normal_scale * sim.params().surfaceThreshold());  // (3.44)
  const BoxState box = sim.boxNow();
  const Boundary& boundary = sim.scene().boundary;
  const float inf = std::numeric_limits<float>::infinity();
  distance.resize(n);
  scratch.resize(n);

  // d_i = 0 on the surface (3.44); else the distance to a boundary when walls count, else unknown.
  // N_max is taken per size class: the classes have different neighbour counts by design (x_SMALL
  // 50, x_LARGE 20, table 3.2), and one global maximum would make every LARGE particle look
  // "isolated" next to SMALL ones, so splitting would creep inwards step after step.
  float max_pressure = 0.0f;
  std::uint32_t max_neighbors_small = 0;
  std::uint32_t max_neighbors_large = 0;
#pragma omp parallel for schedule(static) \
    reduction(max : max_pressure, max_neighbors_small, max_neighbors_large)
  for (std::size_t i = 0; i < n; ++i) {
    float d = inf;
    if (p.normal_length[i] >= surface_threshold) {
      d = 0.0f;
    } else if (config.surface_includes_walls) {
      d = boundaryDistance(p.position[i], box, boundary);
    }
    distance[i] = d;
    max_pressure = std::max(max_pressure, p.pressure[i]);
    if (p.size_class[i] == SizeClass::Small) {
      max_neighbors_small = std::max(max_neighbors_small, grid.neighborCount(i));
    } else {
      max_neighbors_large = std::max(max_neighbors_large, grid.neighborCount(i));
    }
  }

  // Propagate: d_i = min(d_i, d_j + |r_ij|) over neighbours, Jacobi style (reads one buffer, writes
  // the other) so the result does not depend on the order particles are visited in.
  for (int hop = 0; hop < config.surface_hops; ++hop) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      float d = distance[i];
      const Vec3 xi = p.position[i];
      for (std::uint32_t j : grid.neighbors(i)) {
        const float dj = distance[j];
        if (dj < d) d = std::min(d, dj + (xi - p.position[j]).norm());
      }
      scratch[i] = d;
    }
    distance.swap(scratch);
  }

  float max_distance = 0.0f;
#pragma omp parallel for schedule(static) reduction(max : max_distance)
  for (std::size_t i = 0; i < n; ++i) {
    if (distance[i] < inf) max_distance = std::max(max_distance, distance[i]);
  }

  // Character field, eq. (3.45), and the decision, eq. (3.46). Particles the propagation did not
  // reach are deeper than every reached one: they take d = dmax.
  const float alpha = static_cast<float>(config.alpha);
  const float beta = static_cast<float>(config.beta);
  const float gamma = static_cast<float>(config.gamma);
  const float inv_weights = 1.0f / (alpha + beta + gamma);
  const float inv_dmax = max_distance > 0.0f ? 1.0f / max_distance : 0.0f;
  const float inv_fmax = max_pressure > 0.0f ? 1.0f / max_pressure : 0.0f;
  const auto inverse = [](std::uint32_t v) { return v > 0 ? 1.0f / static_cast<float>(v) : 0.0f; };
  const float inv_nmax[kSizeClassCount] = {inverse(max_neighbors_small),
                                           inverse(max_neighbors_large)};
  const float split_below = static_cast<float>(config.threshold);
  const float merge_from = 2.0f * split_below;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const float d = std::min(distance[i], max_distance);
    const float f = std::max(p.pressure[i], 0.0f);
    const float cf = (alpha * d * inv_dmax + beta * (1.0f - f * inv_fmax) +
                      gamma * static_cast<float>(grid.neighborCount(i)) *
                          inv_nmax[classIndex(p.size_class[i])]) *
                     inv_weights;
    out[i] = cf < split_below ? kSplit : (cf >= merge_from ? kMerge : kRemain);
  }
}

void decideByGaze(const ParticleSet& particles, const ScreenCamera& camera, double gaze_x,
                  double gaze_y, const AdaptiveConfig& config, std::span<std::int8_t> out) {
  const Projector projector(camera);
  const double inv_aspect = 1.0 / projector.aspect();
  const std::size_t n = particles.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const ScreenDisc disc =
        projector.project(particles.position[i].cast<double>(), particles.radius[i]);
    if (!disc.in_front) {
      out[i] = kMerge;
      continue;
    }
    // Distances in units of the viewport width (y is a fraction of the height).
    const double dx = disc.x - gaze_x;
    const double dy = (disc.y - gaze_y) * inv_aspect;
    const double dist2 = dx * dx + dy * dy;
    const double inner = config.gaze_radius + disc.radius;
    const double outer = config.gaze_ring_radius + disc.radius;
    // eq. (3.47): f = sgn(|r_i - r_gaze|^2 - (r_i + r_gaze)^2); SPLIT where f < 0 (3.48).
    out[i] = dist2 < inner * inner ? kSplit : (dist2 > outer * outer ? kMerge : kRemain);
  }
}

void combineHybrid(std::span<const std::int8_t> gaze, std::span<std::int8_t> surface_in_out) {
  const std::size_t n = surface_in_out.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const std::int8_t s = surface_in_out[i];
    const std::int8_t g = gaze[i];
    surface_in_out[i] = (g == kSplit && s == kSplit) ? kSplit
                        : (g == kMerge || s == kMerge) ? kMerge
                                                       : kRemain;
  }
}

}  // namespace sph
