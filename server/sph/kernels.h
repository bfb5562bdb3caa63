// Smoothing kernels of Mueller, Charypar and Gross (2003), eqs. (3.1)-(3.5), with per-support-radius
// constants precomputed once, and the averaged kernel of eq. (3.35) for particles of unequal size.
#pragma once

#include <cmath>
#include <numbers>

namespace sph {

struct KernelConstants {
  float h = 0.0f;
  float h2 = 0.0f;
  float poly6 = 0.0f;       // 315 / (64 pi h^9), eq. (3.1)
  float poly6_grad = 0.0f;  // -945 / (32 pi h^9), eqs. (3.2), (3.3)
  float spiky_grad = 0.0f;  // -45 / (pi h^6), eq. (3.4)
  float visc_lap = 0.0f;    // 45 / (pi h^6), eq. (3.5)

  static KernelConstants forSupport(double h) {
    const double pi = std::numbers::pi;
    const double h6 = std::pow(h, 6.0);
    const double h9 = std::pow(h, 9.0);
    KernelConstants k;
    k.h = static_cast<float>(h);
    k.h2 = static_cast<float>(h * h);
    k.poly6 = static_cast<float>(315.0 / (64.0 * pi * h9));
    k.poly6_grad = static_cast<float>(-945.0 / (32.0 * pi * h9));
    k.spiky_grad = static_cast<float>(-45.0 / (pi * h6));
    k.visc_lap = static_cast<float>(45.0 / (pi * h6));
    return k;
  }
};

// W_default(r, h), eq. (3.1); r2 = |r|^2.
inline float poly6(const KernelConstants& k, float r2) {
  if (r2 > k.h2) return 0.0f;
  const float d = k.h2 - r2;
  return k.poly6 * d * d * d;
}

// Scalar factor g such that grad W_default = g * r, eq. (3.2).
inline float poly6GradFactor(const KernelConstants& k, float r2) {
  if (r2 > k.h2) return 0.0f;
  const float d = k.h2 - r2;
  return k.poly6_grad * d * d;
}

// Laplacian of W_default, eq. (3.3).
inline float poly6Laplacian(const KernelConstants& k, float r2) {
  if (r2 > k.h2) return 0.0f;
  return k.poly6_grad * (k.h2 - r2) * (3.0f * k.h2 - 7.0f * r2);
}

// Scalar factor g such that grad W_pressure = g * r, eq. (3.4): -45/(pi h^6) (h - |r|)^2 / |r|.
// Zero at r = 0 (the direction is undefined there; the pair exerts no force).
inline float spikyGradFactor(const KernelConstants& k, float r, float inv_r) {
  if (r > k.h || r <= 0.0f) return 0.0f;
  const float d = k.h - r;
  return k.spiky_grad * d * d * inv_r;
}

// Laplacian of W_viscosity, eq. (3.5).
inline float viscosityLaplacian(const KernelConstants& k, float r) {
  if (r > k.h) return 0.0f;
  return k.visc_lap * (k.h - r);
}

// The cubic spline (M4) kernel of the incompressible solvers (pbf, dfsph), W and its gradient from
// one function, so the density the solvers correct and the gradient they correct it with agree:
//   W(r, h) = sigma f(q), q = r / h, sigma = 8 / (pi h^3),
//   f(q) = 6 (q^3 - q^2) + 1 for q <= 1/2, 2 (1 - q)^3 for 1/2 < q <= 1, 0 beyond,
// with support h (Monaghan 1992 in the compact-support form of SPlisHSPlasH). The gradient is
// grad W = g(r) r_vec with g = dW/dr / r, finite at r = 0 (g(0) = -12 sigma / h^2): no direction
// is needed there, and no division by r for q <= 1/2.
struct CubicKernel {
  float h = 0.0f;
  float inv_h = 0.0f;
  float sigma = 0.0f;       // 8 / (pi h^3)
  float grad_scale = 0.0f;  // sigma / h^2

  static CubicKernel forSupport(double support) {
    CubicKernel k;
    k.h = static_cast<float>(support);
    k.inv_h = static_cast<float>(1.0 / support);
    k.sigma = static_cast<float>(8.0 / (std::numbers::pi * support * support * support));
    k.grad_scale = static_cast<float>(8.0 / (std::numbers::pi * std::pow(support, 5.0)));
    return k;
  }
};

// f(q) of the cubic spline, q >= 0 (the kernel shape with support 1 and sigma 1).
inline float cubicShape(float q) {
  if (q > 1.0f) return 0.0f;
  if (q <= 0.5f) return 6.0f * (q * q * q - q * q) + 1.0f;
  const float d = 1.0f - q;
  return 2.0f * d * d * d;
}

inline float cubicW(const CubicKernel& k, float r) { return k.sigma * cubicShape(r * k.inv_h); }

// g with grad W = g r_vec (see CubicKernel).
inline float cubicGradFactor(const CubicKernel& k, float r) {
  const float q = r * k.inv_h;
  if (q > 1.0f) return 0.0f;
  if (q <= 0.5f) return k.grad_scale * 6.0f * (3.0f * q - 2.0f);
  const float d = 1.0f - q;
  return k.grad_scale * (-6.0f * d * d / q);
}

}  // namespace sph
