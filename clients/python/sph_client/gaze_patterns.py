"""Synthetic gaze: where a pretend user looks at time t (normalized screen, origin top left).

`wandering` is a fixation-and-saccade walk over the screen: it keeps the server's gaze method
splitting and merging in new places all the time, which is what a soak or a load test wants.
Every pattern is deterministic for its seed, so a run can be repeated.
"""

from __future__ import annotations

import math
import random
from typing import Callable

Pattern = Callable[[float], tuple[float, float]]


def fixed(x: float = 0.5, y: float = 0.5) -> Pattern:
    return lambda t: (x, y)


def circle(radius: float = 0.3, period_s: float = 4.0, x: float = 0.5, y: float = 0.5) -> Pattern:
    """Smooth pursuit round a circle."""

    def at(t: float) -> tuple[float, float]:
        a = 2.0 * math.pi * t / period_s
        return x + radius * math.cos(a), y + radius * math.sin(a)

    return at


class Wandering:
    """Fixations of 0.15-0.6 s with a little jitter, joined by 40 ms saccades to a random point
    inside the margin. Query times must not decrease (the walk is generated as time goes on)."""

    def __init__(self, seed: int = 1, margin: float = 0.1, jitter: float = 0.004):
        self._rng = random.Random(seed)
        self._margin = margin
        self._jitter = jitter
        self._from = self._point()
        self._to = self._from
        self._saccade_end = 0.0
        self._fixation_end = self._rng.uniform(0.15, 0.6)

    def _point(self) -> tuple[float, float]:
        lo, hi = self._margin, 1.0 - self._margin
        return self._rng.uniform(lo, hi), self._rng.uniform(lo, hi)

    def __call__(self, t: float) -> tuple[float, float]:
        while t >= self._fixation_end:
            self._from, self._to = self._to, self._point()
            self._saccade_end = self._fixation_end + 0.04
            self._fixation_end = self._saccade_end + self._rng.uniform(0.15, 0.6)
        if t < self._saccade_end:
            s = 1.0 - (self._saccade_end - t) / 0.04
            x = self._from[0] + s * (self._to[0] - self._from[0])
            y = self._from[1] + s * (self._to[1] - self._from[1])
        else:
            x, y = self._to
            x += self._rng.gauss(0.0, self._jitter)
            y += self._rng.gauss(0.0, self._jitter)
        return min(1.0, max(0.0, x)), min(1.0, max(0.0, y))


def by_name(name: str, seed: int = 1) -> Pattern:
    if name == "wandering":
        return Wandering(seed)
    if name == "circle":
        return circle()
    if name == "fixed":
        return fixed()
    raise ValueError(f"unknown gaze pattern {name!r} (known: wandering, circle, fixed)")
