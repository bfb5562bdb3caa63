"""What sph_load observes, phase by phase. Each field has one writer thread (a subscriber writes
its own record, subscriber 0 the server's), or is a Samples that locks its own appends, so the
records need no lock of their own. Memory stays bounded however long the run (stats.Samples)."""

from __future__ import annotations

import collections
import threading
import time
from dataclasses import dataclass, field
from typing import Optional

from .stats import Samples, StepRate


@dataclass
class SubscriberRecord:
    frames: int = 0
    gaps: int = 0
    missed: int = 0
    restarts: int = 0
    bytes: int = 0
    rejected: int = 0
    lag_ms: Samples = field(default_factory=Samples)  # receive wall time - Frame.send_time_us


@dataclass
class ServerRecord:
    """Seen by the lowest-numbered subscriber: the server's state over the phase."""

    steps: StepRate = field(default_factory=StepRate)
    total_ms: Samples = field(default_factory=Samples)
    reported_steps_per_second: Samples = field(default_factory=Samples)
    particles: Samples = field(default_factory=Samples)
    gaze_modes: collections.Counter = field(default_factory=collections.Counter)


@dataclass
class PhaseRecord:
    subscribers: dict = field(default_factory=dict)  # index -> SubscriberRecord
    gaze_sent: dict = field(default_factory=dict)  # publisher index -> samples
    gaze_late: dict = field(default_factory=dict)  # publisher index -> ticks skipped to catch up
    gaze_latency_ms: Samples = field(default_factory=Samples)  # one per (subscriber, echoed sample)
    pose_sent: int = 0
    pose_late: int = 0
    control_sent: int = 0
    control_replied: int = 0
    control_refused: int = 0  # ok = false
    control_timeouts: int = 0
    control_rtt_ms: Samples = field(default_factory=Samples)
    server: ServerRecord = field(default_factory=ServerRecord)


class RunClock:
    """Maps monotonic time to the scenario's phase."""

    def __init__(self, durations: list):
        self.start = time.monotonic()
        self.ends = []
        total = 0.0
        for d in durations:
            total += d
            self.ends.append(total)

    @property
    def end(self) -> float:
        return self.start + self.ends[-1]

    def phase_at(self, now: Optional[float] = None) -> Optional[int]:
        elapsed = (time.monotonic() if now is None else now) - self.start
        for i, end in enumerate(self.ends):
            if elapsed < end:
                return i
        return None


class SentTimes:
    """Send times of one publisher's samples, sequence 1, 2, ...; only the newest `keep` are kept
    (a frame echoes a sample a few steps old: the server holds a sample at most gaze_hold_s)."""

    def __init__(self, keep: int = 1 << 16):
        self._times: collections.deque = collections.deque(maxlen=keep)
        self._appended = 0
        self._lock = threading.Lock()

    def append(self, sent_ns: int) -> None:
        with self._lock:
            self._times.append(sent_ns)
            self._appended += 1

    def get(self, sequence: int) -> Optional[int]:
        with self._lock:
            index = sequence - 1 - (self._appended - len(self._times))
            return self._times[index] if 0 <= index < len(self._times) else None


class GazeRegistry:
    """Send times of our own gaze samples by source_id and sequence, so a frame that echoes a
    sample can be matched to the moment it left."""

    def __init__(self):
        self.sent: dict = {}

    def add_source(self, source_id: str) -> SentTimes:
        self.sent[source_id] = SentTimes()
        return self.sent[source_id]

    def sent_ns(self, source_id: str, sequence: int) -> Optional[int]:
        times = self.sent.get(source_id)
        return None if times is None else times.get(sequence)


class SceneInfo:
    """The container the frames report, for the pose publisher's orbit."""

    def __init__(self):
        self._box = None
        self._ready = threading.Event()

    def set_box(self, lo, hi) -> None:
        if self._box is None:
            self._box = (lo, hi)
            self._ready.set()

    def wait_box(self, timeout_s: float):
        self._ready.wait(timeout_s)
        return self._box


class ThreadCpu:
    """CPU seconds each worker thread used, by role (time.thread_time at the thread's end)."""

    def __init__(self):
        self.by_role: dict = collections.defaultdict(float)
        self._lock = threading.Lock()

    def add(self, role: str, seconds: float) -> None:
        with self._lock:
            self.by_role[role] += seconds
