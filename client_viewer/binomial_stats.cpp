#include "binomial_stats.h"

#include <algorithm>
#include <cmath>

namespace viewer {

namespace {

constexpr double kZ95 = 1.959963984540054;
// Outcomes this close in probability to the observed one count as equally likely (R's binom.test
// uses the same relative tolerance), so rounding does not drop the mirror outcome of a symmetric test.
constexpr double kRelativeTolerance = 1.0 + 1e-7;

double logBinomialProbability(int k, int n, double p) {
  const double log_choose = std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0);
  const double log_p = k > 0 ? k * std::log(p) : 0.0;
  const double log_q = n - k > 0 ? (n - k) * std::log1p(-p) : 0.0;
  return log_choose + log_p + log_q;
}

}  // namespace

Interval wilsonInterval95(int successes, int trials) {
  if (trials <= 0) return {};
  const double n = trials;
  const double p = std::clamp(successes / n, 0.0, 1.0);
  const double z2 = kZ95 * kZ95;
  const double centre = (p + z2 / (2 * n)) / (1 + z2 / n);
  const double half = kZ95 / (1 + z2 / n) * std::sqrt(p * (1 - p) / n + z2 / (4 * n * n));
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

double binomialTestP(int successes, int trials, double chance) {
  if (trials <= 0) return 1.0;
  if (chance <= 0.0) return successes == 0 ? 1.0 : 0.0;
  if (chance >= 1.0) return successes == trials ? 1.0 : 0.0;
  const double observed = logBinomialProbability(successes, trials, chance);
  double p = 0.0;
  for (int k = 0; k <= trials; ++k) {
    const double log_k = logBinomialProbability(k, trials, chance);
    if (log_k <= observed + std::log(kRelativeTolerance)) p += std::exp(log_k);
  }
  return std::min(1.0, p);
}

}  // namespace viewer
