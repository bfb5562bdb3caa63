"""One sph_load run: starts the workers, lets the scenario's phases play out, collects the summary."""

from __future__ import annotations

import datetime
import os
import threading
import time
import uuid
from dataclasses import asdict

import zmq

from ..curve import Security
from ..endpoints import Endpoints
from .records import GazeRegistry, PhaseRecord, RunClock, SceneInfo, ThreadCpu
from .report import FORMAT, merge, phase_summary, summarize
from .scenario import Scenario
from .workers import ControlWorker, GazeWorker, PoseWorker, RunShared, SubscriberWorker, start_workers


def run(scenario: Scenario, endpoints: Endpoints, *, security: Security = Security(), decode: bool = False,
        control_timeout_s: float = 5.0, stop: threading.Event = None) -> dict:
    """Runs the scenario to its end (or until `stop` is set) and returns the JSON summary."""
    stop = stop or threading.Event()
    context = zmq.Context()
    records = [PhaseRecord() for _ in scenario.phases]
    cpu = ThreadCpu()
    started = datetime.datetime.now(datetime.timezone.utc)
    cpu_start = time.process_time()
    clock = RunClock([p.duration_s for p in scenario.phases])
    shared = RunShared(scenario, records, clock, stop, cpu, context, security, GazeRegistry(), SceneInfo(),
                       uuid.uuid4().hex[:8], decode, control_timeout_s)
    workers = []
    workers += start_workers(SubscriberWorker, scenario.max_of("subscribers"), endpoints.frames, shared)
    workers += start_workers(GazeWorker, scenario.max_of("gaze_publishers"), endpoints.gaze, shared)
    if any(p.pose_hz > 0 for p in scenario.phases):
        workers += start_workers(PoseWorker, 1, endpoints.pose, shared)
    if any(p.control_hz > 0 for p in scenario.phases):
        workers += start_workers(ControlWorker, 1, endpoints.control, shared)
    try:
        while time.monotonic() < clock.end and not stop.is_set():
            stop.wait(min(0.2, max(0.0, clock.end - time.monotonic())))
        # Workers end by themselves once the clock has run out; the control worker may wait out
        # its last requests' timeout first.
        for worker in workers:
            worker.join(control_timeout_s + 5.0)
    finally:
        stop.set()
        for worker in workers:
            worker.join(5.0)
        if any(w.is_alive() for w in workers):
            context.destroy(linger=0)  # a hung worker's socket must not keep the tool from ending
        else:
            context.term()
    wall_s = time.monotonic() - clock.start
    cpu_s = time.process_time() - cpu_start
    overall = summarize(merge(records), scenario.duration_s, scenario.max_of("subscribers"),
                        scenario.max_of("gaze_publishers"))
    return {
        "tool": "sph_load",
        "format": FORMAT,
        "started_utc": started.isoformat(timespec="seconds"),
        "wall_s": wall_s,
        "endpoints": asdict(endpoints),
        "curve": security.enabled,
        "decode": decode,
        "scenario": scenario.to_json(),
        "phases": [phase_summary(p, r) for p, r in zip(scenario.phases, records)],
        "overall": overall,
        "tool_cpu": {
            "process_cpu_s": cpu_s,
            "wall_s": wall_s,
            "percent_of_one_core": 100.0 * cpu_s / wall_s if wall_s > 0 else None,
            "machine_cores": os.cpu_count(),
            "by_role_s": dict(cpu.by_role),
        },
        "errors": [f"{w.name}: {w.error!r}" for w in workers if w.error is not None]
        + [f"{w.name}: still running at the end" for w in workers if w.is_alive()],
    }
