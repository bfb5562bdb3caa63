"""Small statistics for sph_load's report: percentiles and rates from observations."""

from __future__ import annotations

import math
from typing import Iterable, Optional, Sequence


def percentile(sorted_values: Sequence[float], q: float) -> Optional[float]:
    """Nearest-rank percentile (q in 0..100) of already sorted values; None when empty. Nearest rank
    keeps p99 an observed value rather than an interpolation between two."""
    if not sorted_values:
        return None
    rank = max(1, math.ceil(q / 100.0 * len(sorted_values)))
    return float(sorted_values[min(rank, len(sorted_values)) - 1])


def distribution(values: Iterable[float]) -> dict:
    """count, p50, p99, max (and min) of the values, in their own unit."""
    ordered = sorted(values)
    return {
        "count": len(ordered),
        "min": float(ordered[0]) if ordered else None,
        "p50": percentile(ordered, 50),
        "p99": percentile(ordered, 99),
        "max": float(ordered[-1]) if ordered else None,
    }


def step_rate(observations: Sequence[tuple[int, int]]) -> Optional[float]:
    """Steps per second from (send_time_us, step) pairs in arrival order: the steps gained over the
    server's own clock. Pairs where the step went backwards (a reset or a new scene) are left out,
    so a reset does not read as a stall."""
    steps = 0
    span_us = 0
    for (t0, s0), (t1, s1) in zip(observations, observations[1:]):
        if s1 >= s0 and t1 > t0:
            steps += s1 - s0
            span_us += t1 - t0
    if span_us <= 0:
        return None
    return steps / (span_us / 1e6)


def fmt_ms(value: Optional[float]) -> str:
    return "-" if value is None else f"{value:.2f}"
