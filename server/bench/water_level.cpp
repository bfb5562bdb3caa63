#include "bench/water_level.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "sph/boundary_volume.h"
#include "sph/kernels.h"
#include "sph/solvers/incompressible_setup.h"

namespace bench {
namespace {

// A gauge's candidates: the particles whose support reaches its vertical line.
struct Candidate {
  double y;
  double horizontal_sq;  // squared distance from the line
  double mass;
  int class_index;  // its kernel: the setup's of its class (every particle of a class has its support)
};

// The walls' volume (boundary_volume.h) in two parts: the floor alone, and the side walls with the
// obstacles. The floor continues the water's lattice below it, so its density adds to the water's
// (a sheet one layer deep on it then reads like the top of deep water); a side wall stands beside
// the water and above it too, so adding it would count wall above the surface as water: it divides
// out instead, the water's sum taken over the part of the kernel the wall leaves to it.
struct Walls {
  sph::IncompressibleSetup setup;  // the solvers' own: each class's kernel and spacing, and the walls
  sph::BoundaryVolume floor;       // the floor alone, with the setup's kernels and spacings
  sph::BoxState floor_only;        // the box's floor, its other faces out of reach
  sph::BoxState sides_only;        // its side faces, floor and roof out of reach
  const sph::BoundaryVolume& sides() const { return *setup.boundary; }
  const sph::CubicKernel& kernel(int class_index) const { return setup.kernels[static_cast<std::size_t>(class_index)]; }
};

sph::Boundary boxAlone(const sph::Boundary& boundary) {
  sph::Boundary out;
  out.box = boundary.box;
  return out;
}

Walls wallsOf(const sph::Scene& scene, const sph::BoxState& box) {
  sph::IncompressibleSetup setup = sph::makeIncompressibleSetup(scene);
  sph::BoundaryVolume floor(boxAlone(scene.boundary), setup.kernels.classes, setup.spacing, scene.params.levels);
  constexpr float kFar = 1e6f;  // metres: beyond any kernel's reach
  Walls walls{std::move(setup), std::move(floor), box, box};
  walls.floor_only.min.x() = walls.floor_only.min.z() = -kFar;
  walls.floor_only.max = sph::Vec3(kFar, kFar, kFar);
  walls.sides_only.min.y() = -kFar;
  walls.sides_only.max.y() = kFar;
  return walls;
}

// Adds particle i to a gauge's candidates at (x, z) where its support reaches the gauge's line.
void addIfReaching(const sph::ParticleSet& p, std::size_t i, double x, double z, std::vector<Candidate>& near) {
  const double hx = p.position[i].x() - x;
  const double hz = p.position[i].z() - z;
  const double h_sq = hx * hx + hz * hz;
  if (h_sq < static_cast<double>(p.support[i]) * p.support[i]) {
    near.push_back({p.position[i].y(), h_sq, p.mass[i], sph::levelIndex(p.level[i])});
  }
}

// A gauge's vertical line at (x, z) and what it reads there.
struct Gauge {
  double x = 0.0;
  double z = 0.0;
  const std::vector<Candidate>* near = nullptr;
  const Walls* walls = nullptr;
  double rest_density = 0.0;
};

// The density at height y on the gauge's line: sum_j m_j W(x - x_j, h_j), with the incompressible
// solvers' cubic spline (kernels.h), plus the floor's rho0 Phi_floor, over 1 - Phi_sides (Walls,
// above); each class's Phi weighted by its share of the water's sum there. Over a half-space at
// rest any symmetric kernel gives rho0 / 2 at the surface.
double densityAt(const Gauge& g, double y) {
  double by_class[sph::kMaxLevels] = {};
  for (const Candidate& c : *g.near) {
    const sph::CubicKernel& kernel = g.walls->kernel(c.class_index);
    const double dy = y - c.y;
    const double r_sq = c.horizontal_sq + dy * dy;
    if (r_sq >= static_cast<double>(kernel.h) * kernel.h) continue;
    by_class[c.class_index] += c.mass * sph::cubicW(kernel, static_cast<float>(std::sqrt(r_sq)));
  }
  double water = 0.0;
  for (double d : by_class) water += d;
  if (water <= 0.0) return 0.0;
  const sph::Vec3 at(static_cast<float>(g.x), static_cast<float>(y), static_cast<float>(g.z));
  double floor_phi = 0.0;
  double sides_phi = 0.0;
  for (int c = 0; c < sph::kMaxLevels; ++c) {
    if (by_class[c] <= 0.0) continue;
    const double share = by_class[c] / water;
    floor_phi += share * g.walls->floor.sample(at, c, g.walls->floor_only).phi;
    sides_phi += share * g.walls->sides().sample(at, c, g.walls->sides_only).phi;
  }
  // A gauge stands at least half an L0 spacing off every side wall and obstacle, where a side's
  // Phi stays under a half (measureWaterLevel); the bound only keeps the quotient finite.
  return (water + g.rest_density * floor_phi) / std::max(1.0 - sides_phi, 0.25);
}

// The highest height on the line where the interpolated density reaches `half` (kg/m^3): stepping
// down from above the highest support in steps of `step`, then halving the bracket. Returns the
// floor's height when it never does (a dry gauge).
double levelOf(const Gauge& g, double floor, double step, double half) {
  double top = floor;
  for (const Candidate& c : *g.near) top = std::max(top, c.y + g.walls->kernel(c.class_index).h);
  double above = top;
  double y = top - step;
  while (y > floor && densityAt(g, y) < half) {
    above = y;
    y -= step;
  }
  if (y <= floor) return floor;
  double below = y;  // density >= half here, < half at `above`
  for (int i = 0; i < 30; ++i) {
    const double mid = 0.5 * (below + above);
    (densityAt(g, mid) >= half ? below : above) = mid;
  }
  return 0.5 * (below + above);
}

// Whether a gauge at (x, z) is at least `reach` from every obstacle.
bool clear(double x, double z, const sph::Boundary& boundary, double reach) {
  for (const sph::Cylinder& c : boundary.cylinders) {
    if (std::hypot(x - c.x, z - c.z) < c.radius + reach) return false;
  }
  for (const sph::Sphere& s : boundary.spheres) {
    if (std::hypot(x - s.centre.x(), z - s.centre.z()) < s.radius + reach) return false;
  }
  return true;
}

// Volume of a sphere between the heights y0 < y1: the integral of pi (r^2 - (y - c)^2).
double sphereSlab(const sph::Sphere& s, double y0, double y1) {
  const double c = s.centre.y();
  const double r = s.radius;
  const double lo = std::max(y0, c - r);
  const double hi = std::min(y1, c + r);
  if (hi <= lo) return 0.0;
  const double cube = (std::pow(hi - c, 3.0) - std::pow(lo - c, 3.0)) / 3.0;
  return std::numbers::pi * (r * r * (hi - lo) - cube);
}

}  // namespace

double incompressibleDepth(double volume, const sph::Boundary& boundary, const sph::BoxState& box) {
  const double floor = box.min.y();
  const double height = box.max.y() - floor;
  const double area = static_cast<double>(box.max.x() - box.min.x()) * (box.max.z() - box.min.z());
  // The water a depth d holds: the box's prism less the obstacles in it (cylinders run floor to
  // roof). An obstacle counts whole when its axis or centre stands over the floor, else not at all
  // (the dam break's obstacles stand outside its box until the box opens).
  auto over = [&](double x, double z) {
    return x >= box.min.x() && x <= box.max.x() && z >= box.min.z() && z <= box.max.z();
  };
  auto held = [&](double d) {
    double v = area * d;
    for (const sph::Cylinder& c : boundary.cylinders) {
      if (over(c.x, c.z)) v -= std::numbers::pi * c.radius * c.radius * d;
    }
    for (const sph::Sphere& s : boundary.spheres) {
      if (over(s.centre.x(), s.centre.z())) v -= sphereSlab(s, floor, floor + d);
    }
    return v;
  };
  if (held(height) <= volume) return height;
  double lo = 0.0;
  double hi = height;
  for (int i = 0; i < 100; ++i) {  // held(d) grows with d
    const double mid = 0.5 * (lo + hi);
    (held(mid) < volume ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double gaugeLevel(const sph::ParticleSet& p, const sph::Scene& scene, const sph::BoxState& box,
                  const std::vector<std::pair<double, double>>& lines) {
  if (p.empty() || lines.empty()) return 0.0;
  double shortest = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    shortest = shortest == 0.0 ? p.support[i] : std::min(shortest, static_cast<double>(p.support[i]));
  }
  const Walls walls = wallsOf(scene, box);
  const double rest_density = scene.params.rest_density;
  const double floor = box.min.y();
  std::vector<Candidate> near;
  double level_sum = 0.0;
  for (const auto& [x, z] : lines) {
    near.clear();
    for (std::size_t i = 0; i < p.size(); ++i) addIfReaching(p, i, x, z, near);
    const Gauge gauge{x, z, &near, &walls, rest_density};
    level_sum += levelOf(gauge, floor, shortest / 8.0, 0.5 * rest_density) - floor;
  }
  return level_sum / static_cast<double>(lines.size());
}

WaterLevel measureWaterLevel(const sph::ParticleSet& p, const sph::Scene& scene, const sph::BoxState& box) {
  WaterLevel out;
  const double rest_density = scene.params.rest_density;
  double mass = 0.0;
  double reach = 0.0;     // the largest support: a gauge's neighbourhood and its grid's step
  double shortest = 0.0;  // the smallest support, for the step of the level search
  for (std::size_t i = 0; i < p.size(); ++i) {
    mass += p.mass[i];
    reach = std::max(reach, static_cast<double>(p.support[i]));
    shortest = shortest == 0.0 ? p.support[i] : std::min(shortest, static_cast<double>(p.support[i]));
  }
  out.incompressible_depth = incompressibleDepth(mass / rest_density, scene.boundary, box);
  if (p.empty() || reach <= 0.0) return out;
  const Walls walls = wallsOf(scene, box);
  // Half an L0 spacing: where a wall layer's particle stands, its line clear of any solid.
  const double half_spacing = 0.5 * walls.setup.spacing[sph::levelIndex(sph::Level{0})];

  // The particles binned into columns of the largest support, so a gauge reads 3 x 3 columns.
  const double x0 = box.min.x();
  const double z0 = box.min.z();
  const int nx = std::max(1, static_cast<int>(std::ceil((box.max.x() - x0) / reach)));
  const int nz = std::max(1, static_cast<int>(std::ceil((box.max.z() - z0) / reach)));
  auto column = [&](double x, double z) {
    const int cx = std::clamp(static_cast<int>(std::floor((x - x0) / reach)), 0, nx - 1);
    const int cz = std::clamp(static_cast<int>(std::floor((z - z0) / reach)), 0, nz - 1);
    return cz * nx + cx;
  };
  std::vector<std::vector<std::size_t>> columns(static_cast<std::size_t>(nx) * nz);
  for (std::size_t i = 0; i < p.size(); ++i) columns[column(p.position[i].x(), p.position[i].z())].push_back(i);

  // One gauge at the centre of each column, so the gauges cover the whole floor in equal shares,
  // up to the walls, whose share of the kernel densityAt accounts for.
  const double floor = box.min.y();
  const double step = shortest / 8.0;
  const double dx = (box.max.x() - x0) / nx;
  const double dz = (box.max.z() - z0) / nz;
  std::vector<Candidate> near;
  double level_sum = 0.0;
  for (int gz = 0; gz < nz; ++gz) {
    for (int gx = 0; gx < nx; ++gx) {
      const Gauge gauge{x0 + (gx + 0.5) * dx, z0 + (gz + 0.5) * dz, &near, &walls, rest_density};
      if (!clear(gauge.x, gauge.z, scene.boundary, half_spacing)) continue;
      near.clear();
      const int home = column(gauge.x, gauge.z);
      for (int oz = -1; oz <= 1; ++oz) {
        for (int ox = -1; ox <= 1; ++ox) {
          const int cx = home % nx + ox;
          const int cz = home / nx + oz;
          if (cx < 0 || cz < 0 || cx >= nx || cz >= nz) continue;
          for (std::size_t i : columns[static_cast<std::size_t>(cz) * nx + cx])
            addIfReaching(p, i, gauge.x, gauge.z, near);
        }
      }
      const double level = levelOf(gauge, floor, step, 0.5 * rest_density) - floor;
      ++out.gauges;
      out.wet += level > 0.0;
      level_sum += level;
    }
  }
  if (out.gauges > 0) out.depth = level_sum / out.gauges;
  return out;
}

}  // namespace bench
