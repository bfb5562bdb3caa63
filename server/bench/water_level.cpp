#include "bench/water_level.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "sph/kernels.h"

namespace bench {
namespace {

// A gauge's candidates: the particles whose support reaches its vertical line.
struct Candidate {
  double y;
  double horizontal_sq;  // squared distance from the line
  double mass;
  sph::CubicKernel kernel;  // of the particle's own support
};

// sum_j m_j W(x - x_j, h_j) at height y on the gauge's line, with the incompressible solvers'
// cubic spline (kernels.h); over a half-space at rest any symmetric kernel gives rho0 / 2 at the
// surface.
double densityAt(const std::vector<Candidate>& near, double y) {
  double sum = 0.0;
  for (const Candidate& c : near) {
    const double dy = y - c.y;
    const double r_sq = c.horizontal_sq + dy * dy;
    if (r_sq >= static_cast<double>(c.kernel.h) * c.kernel.h) continue;
    sum += c.mass * sph::cubicW(c.kernel, static_cast<float>(std::sqrt(r_sq)));
  }
  return sum;
}

// The highest height on the line where the interpolated density reaches `half` (kg/m^3): stepping
// down from above the highest support in steps of `step`, then halving the bracket. Returns the
// floor's height when it never does (a dry gauge).
double levelOf(const std::vector<Candidate>& near, double floor, double step, double half) {
  double top = floor;
  for (const Candidate& c : near) top = std::max(top, c.y + c.kernel.h);
  double above = top;
  double y = top - step;
  while (y > floor && densityAt(near, y) < half) {
    above = y;
    y -= step;
  }
  if (y <= floor) return floor;
  double below = y;  // density >= half here, < half at `above`
  for (int i = 0; i < 30; ++i) {
    const double mid = 0.5 * (below + above);
    (densityAt(near, mid) >= half ? below : above) = mid;
  }
  return 0.5 * (below + above);
}

// Whether a gauge at (x, z) is farther than `reach` from every wall and obstacle.
bool clear(double x, double z, const sph::Boundary& boundary, const sph::BoxState& box, double reach) {
  if (x - box.min.x() < reach || box.max.x() - x < reach) return false;
  if (z - box.min.z() < reach || box.max.z() - z < reach) return false;
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

WaterLevel measureWaterLevel(const sph::ParticleSet& p, const sph::Boundary& boundary, const sph::BoxState& box,
                             double rest_density) {
  WaterLevel out;
  double mass = 0.0;
  double reach = 0.0;     // the largest support: a gauge's neighbourhood, and its distance from walls
  double shortest = 0.0;  // the smallest support, for the step of the level search
  for (std::size_t i = 0; i < p.size(); ++i) {
    mass += p.mass[i];
    reach = std::max(reach, static_cast<double>(p.support[i]));
    shortest = shortest == 0.0 ? p.support[i] : std::min(shortest, static_cast<double>(p.support[i]));
  }
  out.incompressible_depth = incompressibleDepth(mass / rest_density, boundary, box);
  if (p.empty() || reach <= 0.0) return out;

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

  const double floor = box.min.y();
  const double step = shortest / 8.0;
  std::vector<Candidate> near;
  double level_sum = 0.0;
  for (double z = z0 + reach; z <= box.max.z() - reach + 1e-9; z += reach) {
    for (double x = x0 + reach; x <= box.max.x() - reach + 1e-9; x += reach) {
      if (!clear(x, z, boundary, box, reach)) continue;
      near.clear();
      const int home = column(x, z);
      for (int dz = -1; dz <= 1; ++dz) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int cx = home % nx + dx;
          const int cz = home / nx + dz;
          if (cx < 0 || cz < 0 || cx >= nx || cz >= nz) continue;
          for (std::size_t i : columns[static_cast<std::size_t>(cz) * nx + cx]) {
            const double hx = p.position[i].x() - x;
            const double hz = p.position[i].z() - z;
            const double h_sq = hx * hx + hz * hz;
            if (h_sq < static_cast<double>(p.support[i]) * p.support[i]) {
              near.push_back({p.position[i].y(), h_sq, p.mass[i], sph::CubicKernel::forSupport(p.support[i])});
            }
          }
        }
      }
      const double level = levelOf(near, floor, step, 0.5 * rest_density) - floor;
      ++out.gauges;
      out.wet += level > 0.0;
      level_sum += level;
    }
  }
  if (out.gauges > 0) out.depth = level_sum / out.gauges;
  return out;
}

}  // namespace bench
