#include "sph/boundary_volume.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sph {

namespace {

constexpr int kSamples = 512;

// The cubic spline with support h, in units of 1 / m^3.
double kernel(const CubicKernel& k, double r) { return k.sigma * cubicShape(static_cast<float>(r * k.inv_h)); }

// The wall's virtual particles continue the fluid's rest lattice, so each layer (and each row along
// an edge) is summed over that lattice's own points, for a particle on a lattice column: the sums
// below are the in-plane (in-row) lattice sums, in the units of the integrals they stand for (a
// layer's sum times s^2, a row's times s). A continuous in-plane integral is not the lattice's sum:
// for the cubic spline with h = 2 s it gives the first layer's density gradient 2 % of 1 / h less
// than the fluid's lattice, and that mismatch is multiplied by the absolute pressure in the
// pressure force (k_i sum_j grad W_ij + k_i rho0 grad Phi does not vanish), which at a few tens of
// layers' depth is a sizeable fraction of g pushing the wall particles into the wall: the water
// next to the walls never comes to rest. With the lattice's sums, a resting lattice at a face
// has the interior's density and a vanishing density gradient (to float precision).
// `term(t2)` is summed over the in-plane offsets t of a plane (dims = 2) or a row (dims = 1) with
// |t|^2 = t2 within the support.
template <class F>
double latticeSum(const CubicKernel& k, double spacing, double normal2, int dims, F&& term) {
  const int reach = static_cast<int>(std::ceil(k.h / spacing)) + 1;
  double sum = 0.0;
  for (int a = -reach; a <= reach; ++a) {
    for (int b = dims == 2 ? -reach : 0; b <= (dims == 2 ? reach : 0); ++b) {
      const double t2 = spacing * spacing * static_cast<double>(a * a + b * b);
      if (normal2 + t2 >= static_cast<double>(k.h) * k.h) continue;
      sum += term(t2);
    }
  }
  return sum;
}

// A(u): a layer at distance u, s^2 sum_t W(sqrt(u^2 + t^2)) (1 / m; the integral of W over the plane).
double planeSum(const CubicKernel& k, double s, double u) {
  return s * s * latticeSum(k, s, u * u, 2, [&](double t2) { return kernel(k, std::sqrt(u * u + t2)); });
}

// L(rho): a row at distance rho, s sum_z W(sqrt(rho^2 + z^2)) (1 / m^2).
double lineSum(const CubicKernel& k, double s, double rho) {
  return s * latticeSum(k, s, rho * rho, 1, [&](double t2) { return kernel(k, std::sqrt(rho * rho + t2)); });
}

}  // namespace

// Inline: every caller is in this file, and the call would cost as much as the lookup.
inline void BoundaryVolume::Table::at(float x, float& v, float& dv) const {
  const float u = std::max(x - start, 0.0f) * inv_step;
  const auto last = static_cast<float>(value.size() - 1);
  if (u >= last) {
    v = 0.0f;
    dv = 0.0f;
    return;
  }
  const auto i = static_cast<std::size_t>(u);
  const float f = u - static_cast<float>(i);
  v = (1.0f - f) * value[i] + f * value[i + 1];
  dv = (1.0f - f) * slope[i] + f * slope[i + 1];
}

BoundaryVolume::BoundaryVolume(const Boundary& boundary, const std::array<CubicKernel, kMaxLevels>& kernels,
                               const std::array<float, kMaxLevels>& spacing, int levels)
    : kernels_(kernels), spacing_(spacing) {
  // Tables for the run's levels only: no particle is of a coarser one.
  const auto level_count = static_cast<std::size_t>(std::clamp(levels, 1, kMaxLevels));
  // f and f' sampled over [start, start + span], f' by central differences of f.
  const auto tabulate = [](double start, double span, auto&& f) {
    Table t;
    t.start = static_cast<float>(start);
    t.inv_step = static_cast<float>(kSamples / span);
    t.value.resize(kSamples + 1);
    t.slope.resize(kSamples + 1);
    const double eps = 0.25 * span / kSamples;
    for (int i = 0; i <= kSamples; ++i) {
      const double x = start + span * i / kSamples;
      t.value[static_cast<std::size_t>(i)] = static_cast<float>(f(x));
      const double lo = std::max(x - eps, start);
      t.slope[static_cast<std::size_t>(i)] = static_cast<float>((f(x + eps) - f(lo)) / (x + eps - lo));
    }
    t.value.back() = 0.0f;
    t.slope.back() = 0.0f;
    return t;
  };
  for (std::size_t c = 0; c < level_count; ++c) {
    const CubicKernel& k = kernels[c];
    const double s = spacing[c];
    plane_[c] = tabulate(0.0, k.h, [&](double u) { return planeSum(k, s, u); });
    line_[c] = tabulate(0.0, k.h, [&](double rho) { return lineSum(k, s, rho); });
    // A face's layers summed into one function of the distance: one lookup a face, not one a layer.
    face_[c] = tabulate(0.0, k.h, [&](double d) {
      double phi = 0.0;
      for (double u = d + 0.5 * s; u < k.h; u += s) phi += s * planeSum(k, s, u);
      return phi;
    });
  }
  // An obstacle of radius R holds layers of the lattice as shells of radius R - (l + 1/2) s.
  // Sphere: a shell of radius q about the centre at distance D adds s q / D (A(|D - q|) - A(D + q))
  // (the kernel over the sphere, with r^2 = D^2 + q^2 - 2 D q cos theta).
  for (const Sphere& sp : boundary.spheres) {
    std::array<Table, kMaxLevels> tables;
    for (std::size_t c = 0; c < level_count; ++c) {
      const CubicKernel& k = kernels[c];
      const double s = spacing[c];
      const auto plane = [&](double u) {
        float v = 0.0f, unused = 0.0f;
        plane_[c].at(static_cast<float>(u), v, unused);
        return static_cast<double>(v);
      };
      tables[c] = tabulate(sp.radius, k.h, [&](double d) {
        double phi = 0.0;
        for (double q = sp.radius - 0.5 * s; q > 0.0 && q > d - k.h; q -= s) {
          phi += s * q / d * (plane(std::abs(d - q)) - plane(d + q));
        }
        return phi;
      });
    }
    spheres_.push_back(std::move(tables));
    sphere_radius_.push_back(static_cast<float>(sp.radius));
    sphere_centres_.push_back(sp.centre.cast<float>());
  }
  // Cylinder: a shell of radius q adds s q integral over theta of L(|D - q e^{i theta}|).
  const auto shellSum = [](const Table& row, double radius, double s, double h, double d) {
    constexpr int kAngles = 256;
    double sum = 0.0;
    for (double q = radius - 0.5 * s; q > 0.0 && d - q < h; q -= s) {
      double ring = 0.0;
      for (int a = 0; a < kAngles; ++a) {
        const double theta = (a + 0.5) * 2.0 * std::numbers::pi / kAngles;
        const double rho = std::sqrt(std::max(d * d + q * q - 2.0 * d * q * std::cos(theta), 0.0));
        float l = 0.0f, unused = 0.0f;
        row.at(static_cast<float>(rho), l, unused);
        ring += l * 2.0 * std::numbers::pi / kAngles;
      }
      sum += s * q * ring;
    }
    return sum;
  };
  for (const Cylinder& cy : boundary.cylinders) {
    std::array<Table, kMaxLevels> tables;
    for (std::size_t c = 0; c < level_count; ++c) {
      const double h = kernels[c].h, s = spacing[c];
      tables[c] = tabulate(cy.radius, h, [&](double d) { return shellSum(line_[c], cy.radius, s, h, d); });
    }
    cylinders_.push_back(std::move(tables));
    cylinder_radius_.push_back(static_cast<float>(cy.radius));
    cylinder_axes_.emplace_back(static_cast<float>(cy.x), static_cast<float>(cy.z));
  }
}

void BoundaryVolume::boxShare(const float distance[3], const float sign[3], int c, BoundarySample& out) const {
  // Inclusion and exclusion of the solid beyond the three near faces, on the lattice continued
  // into the walls: layers beyond one face (integrated along it), rows beyond two (along the
  // edge), points beyond three. A virtual particle beyond the face of axis a lies at
  // r_a = x_a - x_b = sign_a (d_a + (l + 1/2) s) from the particle (sign: +1 for a min face).
  const auto cu = static_cast<std::size_t>(c);
  const CubicKernel& k = kernels_[cu];
  const Table& face_volume = face_[cu];
  const Table& line = line_[cu];
  const float s = spacing_[cu];
  const int layers = static_cast<int>(std::ceil(k.h / s));
  // Scalars rather than arrays indexed by axis, so that they stay in registers: an array written
  // a float at a time and read back two at a time waits on the store-to-load forwarding.
  float phi = out.phi;
  float d_phi0 = 0.0f, d_phi1 = 0.0f, d_phi2 = 0.0f;  // d Phi / d distance_a
  const bool near0 = distance[0] + 0.5f * s < k.h;
  const bool near1 = distance[1] + 0.5f * s < k.h;
  const bool near2 = distance[2] + 0.5f * s < k.h;
  const auto offset = [&](float d, int l) { return d + (static_cast<float>(l) + 0.5f) * s; };
  const auto face = [&](float d, float& d_phi) {
    float v = 0.0f, dv = 0.0f;
    face_volume.at(d, v, dv);
    phi += v;
    d_phi += dv;
  };
  const auto edge = [&](float da, float db, float& d_phi_a, float& d_phi_b) {
    for (int l = 0; l < layers; ++l) {
      for (int m = 0; m < layers; ++m) {
        const float u = offset(da, l);
        const float w = offset(db, m);
        const float rho = std::sqrt(u * u + w * w);
        if (rho >= k.h) continue;
        float v = 0.0f, dv = 0.0f;
        line.at(rho, v, dv);
        phi -= s * s * v;
        d_phi_a -= s * s * dv * u / rho;
        d_phi_b -= s * s * dv * w / rho;
      }
    }
  };
  if (near0) face(distance[0], d_phi0);
  if (near1) face(distance[1], d_phi1);
  if (near2) face(distance[2], d_phi2);
  if (near0 && near1) edge(distance[0], distance[1], d_phi0, d_phi1);
  if (near0 && near2) edge(distance[0], distance[2], d_phi0, d_phi2);
  if (near1 && near2) edge(distance[1], distance[2], d_phi1, d_phi2);
  if (near0 && near1 && near2) {
    for (int l = 0; l < layers; ++l) {
      for (int m = 0; m < layers; ++m) {
        for (int o = 0; o < layers; ++o) {
          const float u0 = offset(distance[0], l), u1 = offset(distance[1], m), u2 = offset(distance[2], o);
          const float r = std::sqrt(u0 * u0 + u1 * u1 + u2 * u2);
          if (r >= k.h) continue;
          phi += s * s * s * cubicW(k, r);
          const float g = cubicGradFactor(k, r);  // dW/dr / r
          d_phi0 += s * s * s * g * u0;
          d_phi1 += s * s * s * g * u1;
          d_phi2 += s * s * s * g * u2;
        }
      }
    }
  }
  out.phi = phi;
  out.grad = Vec3(d_phi0 * sign[0], d_phi1 * sign[1], d_phi2 * sign[2]);
}

BoundarySample BoundaryVolume::sample(const Vec3& x, int c, const BoxState& box) const {
  BoundarySample out;
  const CubicKernel& k = kernels_[static_cast<std::size_t>(c)];
  float distance[3];
  float sign[3];  // d distance / d x
  float wall_velocity[3];
  bool near = false;
  for (int axis = 0; axis < 3; ++axis) {
    const float to_min = x[axis] - box.min[axis];
    const float to_max = box.max[axis] - x[axis];
    const bool min_side = to_min <= to_max;
    distance[axis] = std::max(min_side ? to_min : to_max, 0.0f);
    sign[axis] = min_side ? 1.0f : -1.0f;
    wall_velocity[axis] = min_side ? box.min_velocity[axis] : box.max_velocity[axis];
    near = near || distance[axis] < k.h;
  }
  if (near) {
    boxShare(distance, sign, c, out);
    for (int axis = 0; axis < 3; ++axis) out.grad_dot_wall_velocity += out.grad[axis] * wall_velocity[axis];
  }
  const auto cu = static_cast<std::size_t>(c);
  for (std::size_t s = 0; s < spheres_.size(); ++s) {
    const Vec3 d = x - sphere_centres_[s];
    const float dist = std::max(d.norm(), sphere_radius_[s]);
    if (dist >= sphere_radius_[s] + k.h) continue;
    float phi = 0.0f, dphi = 0.0f;
    spheres_[s][cu].at(dist, phi, dphi);
    out.phi += phi;
    out.grad += (dphi / dist) * d;
  }
  for (std::size_t s = 0; s < cylinders_.size(); ++s) {
    const float dx = x.x() - cylinder_axes_[s].x();
    const float dz = x.z() - cylinder_axes_[s].y();
    const float dist = std::max(std::sqrt(dx * dx + dz * dz), cylinder_radius_[s]);
    if (dist >= cylinder_radius_[s] + k.h) continue;
    float phi = 0.0f, dphi = 0.0f;
    cylinders_[s][cu].at(dist, phi, dphi);
    out.phi += phi;
    out.grad.x() += dphi * dx / dist;
    out.grad.z() += dphi * dz / dist;
  }
  return out;
}

}  // namespace sph
