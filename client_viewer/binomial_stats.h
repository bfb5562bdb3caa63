// The figures a study's summary gives per comparison: the proportion correct with its 95 % Wilson
// score interval, and the exact two-sided binomial test against chance.
#pragma once

namespace viewer {

struct Interval {
  double low = 0.0;
  double high = 1.0;
};

// Wilson's score interval (Wilson 1927) for `successes` of `trials` at 95 % (z = 1.959964); it
// stays inside [0, 1] and keeps its coverage at small n and near 0 or 1, where the normal
// approximation does not. [0, 1] for no trials.
Interval wilsonInterval95(int successes, int trials);

// The exact two-sided binomial test's p-value (as R's binom.test): the probability, under
// success probability `chance`, of an outcome no more likely than `successes` of `trials`. 1 for
// no trials.
double binomialTestP(int successes, int trials, double chance);

}  // namespace viewer
