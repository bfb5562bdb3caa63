// dfsph's constant-density solve past its first Jacobi iterations: preconditioned conjugate
// gradients with a proximal term (dfsph_solver.h, DfsphSolver::conjugateGradients).
#include <algorithm>
#include <array>
#include <cmath>

#include "sph/solvers/dfsph/dfsph_solver.h"
#include "sph/solvers/ordered_sum.h"

namespace sph {

namespace {

// The proximal weight, and the iterations on one anchor (below). Without the proximal term a
// resting tank keeps moving; a heavier weight calms it further but at many more iterations, and
// one anchor a step kept them from reaching the tolerance (docs/performance.md, "Design
// measurements behind the code").
constexpr float kProximal = 0.05f;
constexpr int kAnchorIterations = 8;

}  // namespace

int DfsphSolver::conjugateGradients(const FrameContext& frame, const DfsphPassForms& forms, float scale,
                                    float tolerance, int least, int iteration) {
  ParticleSet& p = frame.particles;
  const std::size_t n = p.size();
  for (auto* v : {&residual_, &search_, &preconditioned_, &anchor_}) {
    v->reserve(p.capacity());
    v->resize(n);
  }
  active_.reserve(p.capacity());
  active_.resize(n);
  // The system in the k of the particles that push or are compressed (the others stay at 0):
  // B k = b, B = -scale D(a(.)), b = -target. B is symmetric in the mass-weighted product
  // (dfsph_passes.h: D(M^-1 D^T)) and positive semi-definite, so conjugate gradients apply
  // (Saad 2003, algorithm 9.1), preconditioned with B's diagonal (scale / inverse_diagonal).
  // residual_ = b - B k over every particle (> 0: still compressed); change_ holds D(a(k)) on
  // entry. They solve B k + mu diag(B) (k - k_entry) = b, which keeps k near where the Jacobi
  // iterations left it, as Jacobi itself does; without it a resting tank kept moving, and a
  // penalty on k's roughness alone (sum_j |m_j grad W_ij| (k_i - k_j)) did not calm it, so it is
  // the step-to-step change of the smooth k that stirs. The stop is on B's own residual.
  const auto diagonal = [&](std::size_t i) { return scale / inverse_diagonal_[i]; };
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    residual_[i] = scale * change_[i] - target_[i];
    anchor_[i] = stiffness_[i];
    active_[i] = (stiffness_[i] > 0.0f || residual_[i] > 0.0f) && inverse_diagonal_[i] > 0.0f;
    preconditioned_[i] = active_[i] ? residual_[i] / diagonal(i) : 0.0f;
    search_[i] = preconditioned_[i];
  }
  const float* mass = p.mass.data();
  // <r', z> and <s, diag(B) s> in the mass-weighted product (r' = diag(B) z: the regularised
  // system's residual on the active particles): element i's term.
  const auto weighted = [&](const std::vector<float>& x, std::size_t i) {
    return active_[i] ? static_cast<double>(mass[i]) * x[i] * x[i] * diagonal(i) : 0.0;
  };
  // Stops at the tolerance on the mean |residual| (both signs: the iterates overshoot, where
  // Jacobi's approach from one side), not at solve's one-sided mean: element i's term.
  const auto deviation = [&](std::size_t i) {
    return static_cast<double>(active_[i] ? std::abs(residual_[i]) : std::max(residual_[i], 0.0f));
  };
  const double count = static_cast<double>(std::max<std::size_t>(n, 1));
  double rz = orderedSum(n, sum_partials_, [&](std::size_t i) { return weighted(preconditioned_, i); });
  int since_anchor = 0;
  arrays_.stiffness = search_.data();
  while (iteration < frame.scene.params.dfsph_max_iterations && rz > 0.0) {
    pressureAccelerations(forms, frame.grid, true);
    forms.change(arrays_, constants_, frame.grid);  // B search = -scale change_
    // Each iteration's O(n) work in as few sweeps as the sums allow (ordered_sum.h).
    const auto [search_change, search_weighted] = orderedSums<2>(n, sum_partials_, [&](std::size_t i) {
      return std::array<double, 2>{static_cast<double>(mass[i]) * search_[i] * change_[i], weighted(search_, i)};
    });
    const double curvature = -scale * search_change + kProximal * search_weighted;
    if (!(curvature > 0.0)) break;
    const auto alpha = static_cast<float>(rz / curvature);
    const auto [deviation_sum, rz_next] = orderedSums<2>(n, sum_partials_, [&](std::size_t i) {
      stiffness_[i] += alpha * search_[i];
      residual_[i] += alpha * scale * change_[i];
      preconditioned_[i] = active_[i] ? residual_[i] / diagonal(i) - kProximal * (stiffness_[i] - anchor_[i]) : 0.0f;
      return std::array<double, 2>{deviation(i), weighted(preconditioned_, i)};
    });
    ++iteration;
    if (deviation_sum / count <= tolerance && iteration >= least) break;
    if (++since_anchor == kAnchorIterations) {
      // The proximal point method's next step (Rockafellar 1976): anchored at the k reached, so
      // that the solves converge to B k = b where it wants k far from the Jacobi iterations' (a
      // single anchor left small_box's column short of the tolerance until the iteration limit).
      since_anchor = 0;
      rz = orderedSum(n, sum_partials_, [&](std::size_t i) {
        anchor_[i] = stiffness_[i];
        preconditioned_[i] = active_[i] ? residual_[i] / diagonal(i) : 0.0f;
        search_[i] = preconditioned_[i];
        return weighted(preconditioned_, i);
      });
      continue;
    }
    const auto beta = static_cast<float>(rz_next / rz);
    rz = rz_next;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) search_[i] = preconditioned_[i] + beta * search_[i];
  }
  arrays_.stiffness = stiffness_.data();
  // Water pushes, never pulls: the k < 0 the system asks of a few particles are dropped.
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) stiffness_[i] = std::max(stiffness_[i], 0.0f);
  return iteration;
}

}  // namespace sph
