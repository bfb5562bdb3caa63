#include "bench/validation.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bench {

const std::vector<CurvePoint>& martinMoyceN2() {
  // Martin & Moyce 1952, n^2 = 2, as (T, Z).
  static const std::vector<CurvePoint> points = {
      {0.00, 1.00}, {0.41, 1.11}, {0.84, 1.22}, {1.19, 1.44}, {1.43, 1.67}, {1.63, 1.89}, {1.83, 2.11}, {1.98, 2.33},
      {2.20, 2.56}, {2.32, 2.78}, {2.51, 3.00}, {2.65, 3.22}, {2.83, 3.44}, {2.98, 3.67}, {3.11, 3.89}, {3.33, 4.11}};
  return points;
}

const std::vector<CurvePoint>& martinMoyceHeightN2() {
  // Martin & Moyce 1952, n^2 = 2, a = 2.25 in, their Table 6: eta = h / (n^2 a) against
  // tau = t sqrt(g / a) (the table's time carries no n), so T = sqrt(2) tau.
  static const std::vector<CurvePoint> points = [] {
    const double tau_eta[][2] = {{0.00, 1.00}, {0.56, 0.94}, {0.77, 0.89}, {0.93, 0.83}, {1.08, 0.78}, {1.28, 0.72},
                                 {1.46, 0.67}, {1.66, 0.61}, {1.84, 0.56}, {2.00, 0.50}, {2.21, 0.44}, {2.45, 0.39},
                                 {2.70, 0.33}, {3.06, 0.28}, {3.44, 0.22}, {4.20, 0.17}, {5.25, 0.11}, {7.40, 0.06}};
    std::vector<CurvePoint> out;
    for (const auto& p : tau_eta) out.push_back({std::sqrt(2.0) * p[0], p[1]});
    return out;
  }();
  return points;
}

namespace {

// The lattice spacing of the particle's class: the edge of its cube of volume m / rho0.
double spacingOf(const sph::ParticleSet& p, std::size_t i, double rest_density) {
  return std::cbrt(p.mass[i] / rest_density);
}

}  // namespace

double residualHeight(const sph::ParticleSet& p, const sph::Scene& scene, const sph::BoxState& box) {
  const double x = box.min.x() + 0.5 * std::cbrt(scene.params.mass_small / scene.params.rest_density);
  const double z0 = box.min.z();
  const double depth = box.max.z() - z0;
  return gaugeLevel(p, scene, box, {{x, z0 + 0.25 * depth}, {x, z0 + 0.5 * depth}, {x, z0 + 0.75 * depth}});
}

double curveAt(const std::vector<CurvePoint>& curve, double T) {
  if (curve.empty()) return std::numeric_limits<double>::quiet_NaN();
  if (T <= curve.front().T) return curve.front().value;
  for (std::size_t k = 1; k < curve.size(); ++k) {
    if (T <= curve[k].T) {
      const double f = (T - curve[k - 1].T) / (curve[k].T - curve[k - 1].T);
      return curve[k - 1].value + f * (curve[k].value - curve[k - 1].value);
    }
  }
  return std::numeric_limits<double>::quiet_NaN();  // beyond the simulated time: not comparable
}

Column measureColumn(const sph::ParticleSet& p, double rest_density, double wall_x) {
  Column c;
  double compression = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double half = 0.5 * spacingOf(p, i, rest_density);  // to the edge of the particle's volume
    c.width = std::max(c.width, p.position[i].x() + half - wall_x);
    c.height = std::max(c.height, p.position[i].y() + half);
    const double ratio = p.density[i] / rest_density;
    compression += std::max(ratio - 1.0, 0.0);
    c.max_density = std::max(c.max_density, ratio);
  }
  if (!p.empty()) c.mean_compression = compression / static_cast<double>(p.size());
  if (!(c.max_density > 0.0)) {  // no density yet (the thesis's solver and dfsph compute it in their first step)
    c.mean_compression = std::numeric_limits<double>::quiet_NaN();
    c.max_density = std::numeric_limits<double>::quiet_NaN();
  }
  return c;
}

double surgeFrontX(const sph::ParticleSet& p, double rest_density) {
  if (p.empty()) return 0.0;
  std::vector<std::pair<float, std::size_t>> xs(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) xs[i] = {p.position[i].x(), i};
  const std::size_t k = std::min(p.size() - 1, static_cast<std::size_t>(std::floor(0.999 * (p.size() - 1))));
  std::nth_element(xs.begin(), xs.begin() + static_cast<std::ptrdiff_t>(k), xs.end());
  return xs[k].first + 0.5 * spacingOf(p, xs[k].second, rest_density);
}

double maxRelativeError(const std::vector<CurvePoint>& simulated, const std::vector<CurvePoint>& experiment,
                        double t_max, double shift) {
  double worst = 0.0;
  for (const CurvePoint& e : experiment) {
    if (e.T > t_max || e.T == 0.0) continue;  // at T = 0 the value is 1 by definition
    const double z = curveAt(simulated, e.T - shift);
    if (!std::isfinite(z)) return std::numeric_limits<double>::infinity();
    worst = std::max(worst, std::abs(z - e.value) / e.value);
  }
  return worst;
}

double bestStartupShift(const std::vector<CurvePoint>& simulated, const std::vector<CurvePoint>& experiment,
                        double t_max, double max_shift, double& error) {
  double best = 0.0;
  error = maxRelativeError(simulated, experiment, t_max, 0.0);
  // Steps of a thousandth: the simulated curve is interpolated linearly between frames, so the
  // error is continuous in the shift, and a grid of hundredths missed its minimum
  // (docs/validation.md).
  constexpr double kStep = 0.001;
  for (int k = 1; k * kStep <= max_shift + 1e-9; ++k) {
    const double e = maxRelativeError(simulated, experiment, t_max, k * kStep);
    if (e < error) {
      error = e;
      best = k * kStep;
    }
  }
  return best;
}

RestProfile measureRestProfile(const sph::ParticleSet& p, double rest_density, const Eigen::Vector3f& box_min,
                               const Eigen::Vector3f& box_max, double bin_width) {
  RestProfile r;
  if (p.empty()) return r;
  double top = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.size(); ++i) {
    top = std::max(top, p.position[i].y() + 0.5 * spacingOf(p, i, rest_density));
  }
  r.surface_y = top;
  const double depth_max = top - box_min.y();
  const int nbins = std::max(1, static_cast<int>(std::ceil(depth_max / bin_width)));
  r.bins.resize(nbins);
  double speed_sq = 0.0, error_sum = 0.0;
  // The slope's least squares p = c + slope depth over the interior particles: farther than 2.5
  // spacings (beyond the support) from the walls, the floor and the surface, where the walls'
  // and the surface's own layers do not bend the profile.
  double sw = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  double side_sum = 0.0, floor_sum = 0.0;
  int side_n = 0, floor_n = 0;
  double wall_min = std::numeric_limits<double>::infinity(), wall_max = -wall_min;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector3f& x = p.position[i];
    const double depth = top - x.y();
    const int b = std::clamp(static_cast<int>(depth / bin_width), 0, nbins - 1);
    const double ratio = p.density[i] / rest_density;
    r.bins[b].count += 1;
    r.bins[b].density_ratio += ratio;
    r.bins[b].pressure += p.pressure[i];
    error_sum += std::abs(ratio - 1.0);
    speed_sq += p.velocity[i].squaredNorm();
    const double s = spacingOf(p, i, rest_density);
    const double side = std::min({x.x() - box_min.x(), box_max.x() - x.x(), x.z() - box_min.z(), box_max.z() - x.z()});
    if (side > 2.5 * s && x.y() - box_min.y() > 2.5 * s && depth > 2.5 * s) {
      sw += 1.0;
      sx += depth;
      sy += p.pressure[i];
      sxx += depth * depth;
      sxy += depth * p.pressure[i];
    }
    // The layers touching a wall, below the top two layers (the free surface is under-dense by
    // nature: it has no water above it).
    if (depth < 2.0 * s) continue;
    if (x.y() - box_min.y() < s) {
      floor_sum += ratio;
      ++floor_n;
    } else if (x.x() - box_min.x() < s || box_max.x() - x.x() < s || x.z() - box_min.z() < s ||
               box_max.z() - x.z() < s) {
      side_sum += ratio;
      ++side_n;
    } else {
      continue;
    }
    wall_min = std::min(wall_min, ratio);
    wall_max = std::max(wall_max, ratio);
  }
  if (side_n + floor_n > 0) {
    r.wall_min = wall_min;
    r.wall_max = wall_max;
  }
  const double n = static_cast<double>(p.size());
  r.mean_density_error = error_sum / n;
  r.rms_speed = std::sqrt(speed_sq / n);
  if (side_n > 0) r.wall_density_error = std::abs(side_sum / side_n - 1.0);
  if (floor_n > 0) r.wall_density_error = std::max(r.wall_density_error, std::abs(floor_sum / floor_n - 1.0));
  for (int b = 0; b < nbins; ++b) {
    DepthBin& bin = r.bins[b];
    bin.depth = (b + 0.5) * bin_width;
    if (bin.count == 0) continue;
    bin.density_ratio /= bin.count;
    bin.pressure /= bin.count;
  }
  const double denominator = sw * sxx - sx * sx;
  if (denominator > 0.0) r.pressure_slope = (sw * sxy - sx * sy) / denominator;
  return r;
}

}  // namespace bench
