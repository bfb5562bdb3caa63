"""Small statistics for sph_load's report: percentiles and rates from observations."""

from __future__ import annotations

import math
import random
import threading
from typing import Iterable, Optional, Sequence, Union


def percentile(sorted_values: Sequence[float], q: float) -> Optional[float]:
    """Nearest-rank percentile (q in 0..100) of already sorted values; None when empty. Nearest rank
    keeps p99 an observed value rather than an interpolation between two."""
    if not sorted_values:
        return None
    rank = max(1, math.ceil(q / 100.0 * len(sorted_values)))
    return float(sorted_values[min(rank, len(sorted_values)) - 1])


class Samples:
    """Values of one distribution in bounded memory, so a day-long run does not grow without end:
    count, min and max are exact; percentiles come from a uniform sample of at most `capacity`
    values (reservoir sampling, Vitter's algorithm R), exact as long as no more came. Several
    threads may append (a lock: a few hundred appends a second cost nothing)."""

    def __init__(self, values: Iterable[float] = (), capacity: int = 100_000):
        self.capacity = capacity
        self.count = 0
        self.min: Optional[float] = None
        self.max: Optional[float] = None
        self.reservoir: list = []
        self._random = random.Random(12345)
        self._lock = threading.Lock()
        for v in values:
            self.append(v)

    def append(self, value: float) -> None:
        with self._lock:
            self.count += 1
            self.min = value if self.min is None else min(self.min, value)
            self.max = value if self.max is None else max(self.max, value)
            if len(self.reservoir) < self.capacity:
                self.reservoir.append(value)
            else:
                slot = self._random.randrange(self.count)
                if slot < self.capacity:
                    self.reservoir[slot] = value

    def merged(self, others: Sequence["Samples"]) -> "Samples":
        """All of them as one: each contributes to the sample in proportion to its count."""
        total = Samples(capacity=self.capacity)
        everyone = [self, *others]
        n = sum(s.count for s in everyone)
        for s in everyone:
            if not s.count:
                continue
            share = min(len(s.reservoir), math.ceil(self.capacity * s.count / n))
            total.reservoir.extend(total._random.sample(s.reservoir, share))
            total.count += s.count
            total.min = s.min if total.min is None else min(total.min, s.min)
            total.max = s.max if total.max is None else max(total.max, s.max)
        return total

    def __len__(self) -> int:
        return self.count


def distribution(values: Union[Samples, Iterable[float]]) -> dict:
    """count, min, p50, p99 and max of the values, in their own unit."""
    samples = values if isinstance(values, Samples) else Samples(values)
    ordered = sorted(samples.reservoir)
    return {
        "count": samples.count,
        "min": None if samples.min is None else float(samples.min),
        "p50": percentile(ordered, 50),
        "p99": percentile(ordered, 99),
        "max": None if samples.max is None else float(samples.max),
    }


class StepRate:
    """Steps per second from (send_time_us, step) of frames in arrival order: the steps gained over
    the server's own clock. A pair where the step went backwards (a reset, a new scene) is left
    out, so a reset does not read as a stall."""

    def __init__(self):
        self.steps = 0
        self.span_us = 0
        self.frames = 0
        self._last: Optional[tuple[int, int]] = None

    def add(self, send_time_us: int, step: int) -> None:
        self.frames += 1
        if self._last is not None:
            t0, s0 = self._last
            if step >= s0 and send_time_us > t0:
                self.steps += step - s0
                self.span_us += send_time_us - t0
        self._last = (send_time_us, step)

    def merged(self, others: Sequence["StepRate"]) -> "StepRate":
        total = StepRate()
        for r in (self, *others):
            total.steps += r.steps
            total.span_us += r.span_us
            total.frames += r.frames
        return total

    @property
    def rate(self) -> Optional[float]:
        return self.steps / (self.span_us / 1e6) if self.span_us > 0 else None


def step_rate(observations: Sequence[tuple[int, int]]) -> Optional[float]:
    """StepRate over a list of (send_time_us, step) pairs."""
    r = StepRate()
    for t, s in observations:
        r.add(t, s)
    return r.rate


def fmt_ms(value: Optional[float]) -> str:
    return "-" if value is None else f"{value:.2f}"
