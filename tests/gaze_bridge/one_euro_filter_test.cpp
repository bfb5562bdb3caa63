#include "one_euro_filter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

using gaze_bridge::OneEuroFilter;
using gaze_bridge::OneEuroParams;

namespace {

// The reference, written out from Casiez et al. (2012), section "The 1 Euro filter", independently of
// the class: smoothing factor alpha = 1 / (1 + tau / Te) with tau = 1 / (2 pi fc); the derivative
// is the difference to the previous *filtered* value divided by Te, low-passed at dcutoff; the cutoff is
// fcmin + beta |dxhat|.
std::vector<double> reference(const std::vector<double>& x, const std::vector<double>& t, double fcmin, double beta,
                              double dcutoff) {
  const double pi = 3.14159265358979323846;
  std::vector<double> out(x.size());
  double xhat_prev = x[0], dxhat_prev = 0.0;
  out[0] = x[0];
  for (std::size_t i = 1; i < x.size(); ++i) {
    const double te = t[i] - t[i - 1];
    const double dx = (x[i] - xhat_prev) / te;
    const double alpha_d = 1.0 / (1.0 + (1.0 / (2.0 * pi * dcutoff)) / te);
    const double dxhat = alpha_d * dx + (1.0 - alpha_d) * dxhat_prev;
    const double fc = fcmin + beta * std::fabs(dxhat);
    const double alpha = 1.0 / (1.0 + (1.0 / (2.0 * pi * fc)) / te);
    const double xhat = alpha * x[i] + (1.0 - alpha) * xhat_prev;
    out[i] = xhat;
    xhat_prev = xhat;
    dxhat_prev = dxhat;
  }
  return out;
}

}  // namespace

TEST(OneEuroFilter, MatchesReferenceOnFixedInput) {
  // A fixed input: a noisy fixation, a fast jump (saccade), another fixation; uneven sample times.
  const std::vector<double> x = {0.30, 0.302, 0.298, 0.301, 0.299, 0.35, 0.50, 0.65, 0.70, 0.701, 0.699, 0.700, 0.702};
  std::vector<double> t;
  for (std::size_t i = 0; i < x.size(); ++i) t.push_back(0.005 * static_cast<double>(i) + (i % 3 == 2 ? 0.001 : 0.0));
  for (const OneEuroParams params : {OneEuroParams{1.0, 0.0, 1.0}, OneEuroParams{1.0, 1.0, 1.0},
                                     OneEuroParams{0.5, 7.0, 2.0}, OneEuroParams{3.0, 0.007, 1.0}}) {
    const auto expected = reference(x, t, params.min_cutoff_hz, params.beta, params.d_cutoff_hz);
    OneEuroFilter filter(params);
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double dt = i == 0 ? 0.0 : t[i] - t[i - 1];
      EXPECT_NEAR(filter.filter(x[i], dt), expected[i], 1e-14) << "sample " << i << " beta " << params.beta;
    }
  }
}

TEST(OneEuroFilter, SecondSampleByHand) {
  // fc = 1 Hz, beta 0, Te = 0.01 s: tau = 1/(2 pi) = 0.159154943..., alpha = 0.01 / (0.01 + tau)
  // = 0.0591173974...; xhat = 0 + alpha (1 - 0).
  OneEuroFilter filter(OneEuroParams{1.0, 0.0, 1.0});
  EXPECT_EQ(filter.filter(0.0, 0.0), 0.0);
  EXPECT_NEAR(filter.filter(1.0, 0.01), 0.0591173974, 1e-9);
}

TEST(OneEuroFilter, FirstSamplePassesAndConstantStaysConstant) {
  OneEuroFilter filter;
  EXPECT_EQ(filter.filter(0.42, 0.0), 0.42);
  for (int i = 0; i < 100; ++i) EXPECT_DOUBLE_EQ(filter.filter(0.42, 0.01), 0.42);
  filter.reset();
  EXPECT_FALSE(filter.initialized());
  EXPECT_EQ(filter.filter(0.9, 0.01), 0.9);  // after reset: no memory of 0.42
}

TEST(OneEuroFilter, HigherBetaFollowsAStepFaster) {
  OneEuroFilter slow(OneEuroParams{1.0, 0.0, 1.0});
  OneEuroFilter fast(OneEuroParams{1.0, 5.0, 1.0});
  slow.filter(0.2, 0.0);
  fast.filter(0.2, 0.0);
  double s = 0, f = 0;
  for (int i = 0; i < 10; ++i) {
    s = slow.filter(0.8, 0.005);
    f = fast.filter(0.8, 0.005);
  }
  EXPECT_GT(f, s);
  EXPECT_LT(f, 0.8);
}

TEST(OneEuroFilter, RejectsBadParameters) {
  EXPECT_THROW(OneEuroFilter(OneEuroParams{0.0, 1.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(OneEuroFilter(OneEuroParams{1.0, -1.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(OneEuroFilter(OneEuroParams{1.0, 1.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(OneEuroFilter(OneEuroParams{std::nan(""), 1.0, 1.0}), std::invalid_argument);
}
