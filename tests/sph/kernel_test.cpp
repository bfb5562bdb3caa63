// Smoothing kernels, eqs. (3.1)-(3.5): normalisation on the rest lattice, and gradients and
// Laplacians against central finite differences of the kernel values.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <numbers>
#include <vector>

#include "sph/kernels.h"
#include "sph/params.h"

namespace {

using sph::KernelConstants;

// Sum of W(|x|, h) * V over a cubic lattice of spacing a, the evaluation point at a node.
double latticeSum(const KernelConstants& k, double a) {
  const int n = static_cast<int>(std::ceil(static_cast<double>(k.h) / a)) + 1;
  double sum = 0.0;
  for (int x = -n; x <= n; ++x) {
    for (int y = -n; y <= n; ++y) {
      for (int z = -n; z <= n; ++z) {
        const double r2 = a * a * (x * x + y * y + z * z);
        sum += sph::poly6(k, static_cast<float>(r2));
      }
    }
  }
  return sum * a * a * a;
}

// Sample points strictly inside the support, away from the axes and from r = 0 and r = h.
std::vector<Eigen::Vector3d> samplePoints(double h) {
  std::vector<Eigen::Vector3d> pts;
  const Eigen::Vector3d dirs[] = {Eigen::Vector3d(1.0, 0.3, -0.2), Eigen::Vector3d(-0.4, 0.9, 0.5),
                                  Eigen::Vector3d(0.2, -0.7, -1.0)};
  for (const auto& d : dirs) {
    for (double f : {0.15, 0.4, 0.65, 0.85}) pts.push_back(d.normalized() * (f * h));
  }
  return pts;
}

// Spiky kernel W = 15 / (pi h^6) (h - r)^3, written here as the reference for eq. (3.4).
double spiky(double h, double r) {
  if (r > h) return 0.0;
  return 15.0 / (std::numbers::pi * std::pow(h, 6.0)) * std::pow(h - r, 3.0);
}

double poly6At(const KernelConstants& k, const Eigen::Vector3d& x) {
  return sph::poly6(k, static_cast<float>(x.squaredNorm()));
}

template <typename F>
Eigen::Vector3d centralGradient(F f, const Eigen::Vector3d& x, double eps) {
  Eigen::Vector3d g;
  for (int a = 0; a < 3; ++a) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(a) * eps;
    g[a] = (f(x + e) - f(x - e)) / (2.0 * eps);
  }
  return g;
}

// Runs `check(props, kernel)` once per size class of the thesis preset.
template <typename F>
void forEachClass(F check) {
  const sph::SimParams params = sph::thesisPreset();
  for (sph::Level c : {sph::Level{0}, sph::Level{1}}) {
    SCOPED_TRACE(sph::levelName(c));
    const sph::LevelProps props = params.levelProps()[sph::levelIndex(c)];
    check(props, KernelConstants::forSupport(props.support));
  }
}

TEST(Kernel, Poly6SumsToOneOnRestLattice) {
  forEachClass([](const sph::LevelProps& props, const KernelConstants& k) {
    const double spacing = std::cbrt(props.mass / sph::thesisPreset().rest_density);
    EXPECT_NEAR(latticeSum(k, spacing), 1.0, 0.05);
  });
}

TEST(Kernel, Poly6GradientMatchesFiniteDifference) {
  forEachClass([](const sph::LevelProps&, const KernelConstants& k) {
    const double h = k.h;
    const double scale = 945.0 / (32.0 * std::numbers::pi * std::pow(h, 9.0)) * std::pow(h, 5.0);
    for (const auto& x : samplePoints(h)) {
      const auto f = [&](const Eigen::Vector3d& p) { return poly6At(k, p); };
      const Eigen::Vector3d fd = centralGradient(f, x, 1e-3 * h);
      const Eigen::Vector3d analytic =
          static_cast<double>(sph::poly6GradFactor(k, static_cast<float>(x.squaredNorm()))) * x;
      EXPECT_LT((analytic - fd).norm(), 1e-3 * scale) << "at |r|/h = " << x.norm() / h;
    }
  });
}

TEST(Kernel, SpikyGradientMatchesFiniteDifference) {
  forEachClass([](const sph::LevelProps&, const KernelConstants& k) {
    const double h = k.h;
    const double scale = 45.0 / (std::numbers::pi * std::pow(h, 4.0));
    for (const auto& x : samplePoints(h)) {
      const auto f = [&](const Eigen::Vector3d& p) { return spiky(h, p.norm()); };
      const Eigen::Vector3d fd = centralGradient(f, x, 1e-5 * h);
      const float r = static_cast<float>(x.norm());
      const Eigen::Vector3d analytic = static_cast<double>(sph::spikyGradFactor(k, r, 1.0f / r)) * x;
      EXPECT_LT((analytic - fd).norm(), 1e-5 * scale) << "at |r|/h = " << x.norm() / h;
    }
    EXPECT_EQ(sph::spikyGradFactor(k, 1.01f * k.h, 1.0f / (1.01f * k.h)), 0.0f);
  });
}

TEST(Kernel, Poly6LaplacianMatchesFiniteDifference) {
  forEachClass([](const sph::LevelProps&, const KernelConstants& k) {
    const double h = k.h;
    const double scale = 945.0 / (32.0 * std::numbers::pi * std::pow(h, 9.0)) * std::pow(h, 4.0);
    const double eps = 1e-2 * h;
    for (const auto& x : samplePoints(h)) {
      double lap = 0.0;
      for (int a = 0; a < 3; ++a) {
        const Eigen::Vector3d e = Eigen::Vector3d::Unit(a) * eps;
        lap += (poly6At(k, x + e) - 2.0 * poly6At(k, x) + poly6At(k, x - e)) / (eps * eps);
      }
      const double analytic = sph::poly6Laplacian(k, static_cast<float>(x.squaredNorm()));
      EXPECT_LT(std::abs(analytic - lap), 1e-2 * scale) << "at |r|/h = " << x.norm() / h;
    }
    EXPECT_EQ(sph::poly6Laplacian(k, 1.01f * k.h2), 0.0f);
  });
}

TEST(Kernel, ViscosityLaplacianMatchesFormula) {
  forEachClass([](const sph::LevelProps&, const KernelConstants& k) {
    const double h = k.h;
    const double c = 45.0 / (std::numbers::pi * std::pow(h, 6.0));
    for (double f : {0.0, 0.2, 0.5, 0.9, 1.0}) {
      const double r = f * h;
      const double expected = c * (h - r);
      EXPECT_NEAR(sph::viscosityLaplacian(k, static_cast<float>(r)), expected, 1e-5 * c * h + 1e-6) << "at r/h = " << f;
    }
    EXPECT_EQ(sph::viscosityLaplacian(k, 1.001f * k.h), 0.0f);
    EXPECT_EQ(sph::viscosityLaplacian(k, 2.0f * k.h), 0.0f);
  });
}

}  // namespace
