"""sph_load's worker threads: one per frame subscriber, one per gaze publisher, one for poses, one
for control. Every worker exists for the whole run and is active in the phases whose counts or
rates include it; publishers pace themselves to absolute deadlines, so a late tick is caught up by
skipping (and counted) rather than by bursting.
"""

from __future__ import annotations

import math
import threading
import time
from dataclasses import dataclass
from typing import Iterator, Optional

import numpy as np
import zmq

from .. import gaze_patterns
from ..control import ControlClient
from ..curve import Security
from ..frames import FrameSubscriber, decode_frame
from ..proto import pb
from ..publishers import GazePublisher, PosePublisher
from .records import GazeRegistry, PhaseRecord, RunClock, SceneInfo, SubscriberRecord, ThreadCpu
from .scenario import Phase, Scenario, verb_arguments

POLL_S = 0.1  # how long a worker waits before looking at the clock and the stop flag again
BOX_WAIT_S = 5.0  # how long the pose publisher waits for a frame to tell it the container


@dataclass
class RunShared:
    """What every worker of one run shares."""

    scenario: Scenario
    records: list  # PhaseRecord per phase
    clock: RunClock
    stop: threading.Event
    cpu: ThreadCpu
    context: zmq.Context
    security: Security
    registry: GazeRegistry
    scene: SceneInfo
    run_id: str
    decode: bool = False
    control_timeout_s: float = 5.0


class Worker(threading.Thread):
    role = "worker"

    def __init__(self, index: int, endpoint: str, shared: RunShared):
        super().__init__(name=f"{self.role}-{index}", daemon=True)
        self.index = index
        self.endpoint = endpoint
        self.shared = shared
        self.scenario = shared.scenario
        self.records = shared.records
        self.stop_event = shared.stop
        self.error: Optional[BaseException] = None

    def phases(self) -> Iterator[tuple[int, Phase]]:
        """(index, config) of the current phase, again and again, until the run is over or stopped."""
        while not self.stop_event.is_set():
            phase = self.shared.clock.phase_at()
            if phase is None:
                return
            yield phase, self.scenario.phases[phase]

    def socket_options(self) -> dict:
        security = self.shared.security
        return {
            "context": self.shared.context,
            "curve_secret": security.curve_secret,
            "curve_server": security.curve_server,
        }

    def run(self) -> None:
        try:
            self.work()
        except BaseException as error:  # reported in the summary; one worker must not hide it
            self.error = error
        finally:
            self.shared.cpu.add(self.role, time.thread_time())

    def work(self) -> None:
        raise NotImplementedError


class Ticker:
    """Absolute-deadline pacing at a rate that may change between phases."""

    def __init__(self):
        self.next: Optional[float] = None
        self.rate = 0.0

    def reset(self) -> None:
        self.next = None

    def wait(self, rate_hz: float, stop: threading.Event) -> tuple[bool, int]:
        """Sleeps towards the next tick (at most POLL_S); returns (due, ticks skipped to catch up)."""
        now = time.monotonic()
        if rate_hz != self.rate or self.next is None:
            self.rate, self.next = rate_hz, now
        skipped = 0
        if now - self.next > 1.0 / rate_hz:  # more than a period behind: skip, do not burst
            skipped = int((now - self.next) * rate_hz)
            self.next += skipped / rate_hz
        delay = self.next - now
        if delay > 0:
            stop.wait(min(delay, POLL_S))
            if time.monotonic() < self.next:
                return False, skipped
        self.next += 1.0 / rate_hz
        return True, skipped


class SubscriberWorker(Worker):
    role = "subscriber"

    def work(self) -> None:
        subscriber: Optional[FrameSubscriber] = None
        last_seen: dict = {}
        last_sequence: Optional[int] = None
        try:
            for phase, config in self.phases():
                active = self.index < config.subscribers
                if active and subscriber is None:
                    # A deep receive queue: when frames are lost, the server dropped them, not us.
                    subscriber = FrameSubscriber(self.endpoint, rcvhwm=1000, **self.socket_options())
                    last_seen, last_sequence = {}, None
                elif not active and subscriber is not None:
                    subscriber.close()
                    subscriber = None
                if subscriber is None:
                    self.stop_event.wait(POLL_S)
                    continue
                data = subscriber.recv_bytes(POLL_S)
                if data is None:
                    continue
                last_sequence = self._frame(data, phase, last_seen, last_sequence)
        finally:
            if subscriber is not None:
                subscriber.close()

    def _frame(self, data: bytes, phase: int, last_seen: dict, last_sequence: Optional[int]) -> Optional[int]:
        received_ns = time.monotonic_ns()
        received_wall_us = time.time_ns() // 1000
        record = self.records[phase].subscribers.setdefault(self.index, SubscriberRecord())
        message = pb.Frame()
        try:
            message.ParseFromString(data)
            if self.shared.decode:
                decode_frame(message)
        except Exception:  # a frame that does not decode is counted, never fatal
            record.rejected += 1
            return last_sequence
        record.frames += 1
        record.bytes += len(data)
        record.lag_ms.append((received_wall_us - message.send_time_us) / 1000.0)
        sequence = message.sequence
        if last_sequence is not None:
            if sequence > last_sequence + 1:
                record.gaps += 1
                record.missed += sequence - last_sequence - 1
            elif sequence <= last_sequence:
                record.restarts += 1
        self._gaze_latency(message, received_ns, last_seen, self.records[phase])
        if self.index == 0:
            self._server(message, self.records[phase])
        return sequence

    def _gaze_latency(self, message, received_ns: int, last_seen: dict, record: PhaseRecord) -> None:
        source = message.gaze.source_id
        sequence = message.gaze.sample_sequence
        if sequence <= last_seen.get(source, 0):
            return  # a sample this subscriber has already seen used: only the first frame counts
        sent_ns = self.shared.registry.sent_ns(source, sequence)
        if sent_ns is None:
            return  # not one of ours (or no gaze yet)
        last_seen[source] = sequence
        record.gaze_latency_ms.append((received_ns - sent_ns) / 1e6)

    def _server(self, message, record: PhaseRecord) -> None:
        server = record.server
        server.steps.add(message.send_time_us, message.step)
        server.total_ms.append(message.timings.total_ms)
        server.reported_steps_per_second.append(message.steps_per_second)
        server.particles.append(message.particle_count)
        server.gaze_modes[pb.GazeMode.Name(message.gaze.mode)] += 1
        if message.geometry.HasField("box"):
            lo, hi = message.geometry.box.min, message.geometry.box.max
            self.shared.scene.set_box(np.array([lo.x, lo.y, lo.z]), np.array([hi.x, hi.y, hi.z]))


class GazeWorker(Worker):
    role = "gaze"

    def __init__(self, index: int, endpoint: str, shared: RunShared):
        super().__init__(index, endpoint, shared)
        self.source_id = f"sph_load-{shared.run_id}-{index}"
        self.sent_times = shared.registry.add_source(self.source_id)

    def work(self) -> None:
        publisher = GazePublisher(self.endpoint, source_id=self.source_id, **self.socket_options())
        patterns: dict = {}
        ticker = Ticker()
        try:
            for phase, config in self.phases():
                if self.index >= config.gaze_publishers:
                    ticker.reset()
                    self.stop_event.wait(POLL_S)
                    continue
                due, skipped = ticker.wait(config.gaze_hz, self.stop_event)
                record = self.records[phase]
                if skipped:
                    record.gaze_late[self.index] = record.gaze_late.get(self.index, 0) + skipped
                if not due:
                    continue
                if config.gaze_pattern not in patterns:
                    patterns[config.gaze_pattern] = gaze_patterns.by_name(config.gaze_pattern, seed=self.index + 1)
                x, y = patterns[config.gaze_pattern](time.monotonic() - self.shared.clock.start)
                self.sent_times.append(time.monotonic_ns())  # before the send: an echo can never beat it
                publisher.send(x, y)
                record.gaze_sent[self.index] = record.gaze_sent.get(self.index, 0) + 1
        finally:
            publisher.close()


class PoseWorker(Worker):
    """One viewer orbiting the container once every 20 s, looking at its centre."""

    role = "pose"

    def __init__(self, index: int, endpoint: str, shared: RunShared):
        super().__init__(index, endpoint, shared)
        self.viewer_id = f"sph_load-{shared.run_id}"

    def work(self) -> None:
        publisher = PosePublisher(self.endpoint, viewer_id=self.viewer_id, **self.socket_options())
        ticker = Ticker()
        box = None
        try:
            for phase, config in self.phases():
                rate = config.pose_hz
                if rate <= 0:
                    ticker.reset()
                    self.stop_event.wait(POLL_S)
                    continue
                if box is None:
                    # The first frame tells where the container is; a phase with no subscriber
                    # never learns it, and then a 1 m cube at the origin stands in.
                    box = self.shared.scene.wait_box(POLL_S)
                    if box is None and time.monotonic() - self.shared.clock.start > BOX_WAIT_S:
                        box = (np.zeros(3), np.ones(3))
                    continue
                due, skipped = ticker.wait(rate, self.stop_event)
                record = self.records[phase]
                record.pose_late += skipped
                if not due:
                    continue
                lo, hi = box
                centre = (lo + hi) / 2.0
                distance = 1.5 * float(np.linalg.norm(hi - lo))
                angle = 2.0 * math.pi * (time.monotonic() - self.shared.clock.start) / 20.0
                eye = centre + np.array([distance * math.sin(angle), 0.6 * distance, distance * math.cos(angle)])
                publisher.send_look_at(eye, centre, far=4.0 * distance)
                record.pose_sent += 1
        finally:
            publisher.close()


class ControlWorker(Worker):
    """Requests at the phase's rate, cycling through its verbs, several in flight when the server is
    slow. The worker waits on the socket, not on a timer, so a reply is timed when it arrives; a
    request unanswered after control_timeout_s counts as a timeout."""

    role = "control"
    MAX_IN_FLIGHT = 64

    def work(self) -> None:
        client = ControlClient(self.endpoint, **self.socket_options())
        in_flight: dict = {}  # request id -> (sent ns, phase)
        next_send: Optional[float] = None
        rate = 0.0
        turn = 0
        try:
            for phase, config in self.phases():
                now = time.monotonic()
                wait = POLL_S
                if config.control_hz > 0:
                    if next_send is None or rate != config.control_hz:
                        next_send, rate = now, config.control_hz
                    if now >= next_send:
                        if len(in_flight) < self.MAX_IN_FLIGHT:
                            verb, arguments = verb_arguments(config.control_verbs[turn % len(config.control_verbs)])
                            turn += 1
                            in_flight[client.send(verb, **arguments)] = (time.monotonic_ns(), phase)
                            self.records[phase].control_sent += 1
                        next_send = max(next_send + 1.0 / rate, now)  # no burst after a stall
                    wait = min(wait, max(0.0, next_send - time.monotonic()))
                else:
                    next_send = None
                self._collect(client, in_flight, wait)
            # The run is over: requests still out get their full time to answer.
            deadline = time.monotonic() + self.shared.control_timeout_s
            while in_flight and time.monotonic() < deadline and not self.stop_event.is_set():
                self._collect(client, in_flight, POLL_S)
            self._expire(in_flight, force=True)
        finally:
            client.close()

    def _collect(self, client: ControlClient, in_flight: dict, wait_s: float) -> None:
        reply = client.recv_reply(wait_s)
        while reply is not None:
            sent = in_flight.pop(reply.request_id, None)
            if sent is not None:
                record = self.records[sent[1]]
                record.control_replied += 1
                record.control_rtt_ms.append((time.monotonic_ns() - sent[0]) / 1e6)
                if not reply.ok:
                    record.control_refused += 1
            reply = client.recv_reply(0.0)
        self._expire(in_flight)

    def _expire(self, in_flight: dict, force: bool = False) -> None:
        limit = time.monotonic_ns() - int(self.shared.control_timeout_s * 1e9)
        for request_id, (sent_ns, phase) in list(in_flight.items()):
            if force or sent_ns < limit:
                del in_flight[request_id]
                self.records[phase].control_timeouts += 1


def start_workers(kind: type, count: int, endpoint: str, shared: RunShared) -> list:
    workers = [kind(i, endpoint, shared) for i in range(count)]
    for worker in workers:
        worker.start()
    return workers
