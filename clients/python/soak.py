#!/usr/bin/python3
"""Soak test of sph_server (not in CI: it runs for minutes). Starts build/bin/sph_server on free
loopback ports (wave scene, gaze method by default), drives it with sph_load's gaze publisher on a
wandering pattern plus one frame subscriber, and checks every frame it receives:

- no NaN or infinite position;
- no particle outside Frame.geometry.box (the box as it stands at the frame's sim time, so the wave
  scene's moving wall is followed), with the 1e-4 m slack the scenario tests allow;
- the server's resident memory (VmRSS of /proc/PID/status) grows < 5 % from the first minute to the
  end (the median of 10 s after the first minute against the median of the last 10 s: one sample
  would read an allocation in flight as growth);
- no step slower than 3x the median step (Frame.timings.total_ms of the published steps).

Prints a verdict and the figures; exit code 0 when every check passed.

    /usr/bin/python3 clients/python/soak.py                    # 10 minutes
    /usr/bin/python3 clients/python/soak.py --duration 120 --json soak.json
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import numpy as np  # noqa: E402

from sph_client import FrameSubscriber, decode_frame, pb  # noqa: E402
from sph_client.load import runner  # noqa: E402
from sph_client.load.scenario import single_phase  # noqa: E402
from sph_client.load.stats import distribution  # noqa: E402
from sph_client.local_server import LocalServer  # noqa: E402

SLACK_M = 1e-4  # as tests/bench/scenario_health_test.cpp: a float hair outside is not "outside"
MEMORY_WINDOW_S = 10.0


def rss_kib(pid: int) -> int | None:
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
    except OSError:
        return None
    return None


def cpu_jiffies() -> list:
    """The machine's `cpu` line of /proc/stat: user nice system idle iowait irq softirq steal ..."""
    with open("/proc/stat") as f:
        return [int(v) for v in f.readline().split()[1:]]


def load_average() -> float:
    with open("/proc/loadavg") as f:
        return float(f.read().split()[0])


class MemorySampler(threading.Thread):
    def __init__(self, pid: int, interval_s: float = 1.0):
        super().__init__(daemon=True)
        self.pid = pid
        self.interval_s = interval_s
        self.samples: list = []  # (seconds since start, KiB)
        self.load: list = []  # 1-minute load average, once a second
        self.stop = threading.Event()
        self.start_time = time.monotonic()

    def run(self) -> None:
        while not self.stop.is_set():
            value = rss_kib(self.pid)
            if value is not None:
                self.samples.append((time.monotonic() - self.start_time, value))
            self.load.append(load_average())
            self.stop.wait(self.interval_s)

    def median_between(self, t0: float, t1: float) -> float | None:
        values = [v for t, v in self.samples if t0 <= t <= t1]
        return statistics.median(values) if values else None


class FrameChecker:
    def __init__(self):
        self.frames = 0
        self.nan_frames = 0
        self.nan_values = 0
        self.outside_frames = 0
        self.outside_particles = 0
        self.worst_outside_m = 0.0
        self.no_box_frames = 0
        self.total_ms: list = []  # (sim_time, step, total_ms)
        self.particles: list = []
        self.gaze_modes: dict = {}
        self.first_problem: str | None = None

    def check(self, frame) -> None:
        self.frames += 1
        m = frame.message
        positions = frame.positions
        finite = np.isfinite(positions)
        if not finite.all():
            self.nan_frames += 1
            self.nan_values += int((~finite).sum())
            self.first_problem = self.first_problem or f"step {m.step}: {int((~finite).sum())} non-finite values"
        box = frame.box()
        if box is None:
            self.no_box_frames += 1
        else:
            lo, hi = box
            below = (lo - SLACK_M) - positions
            above = positions - (hi + SLACK_M)
            outside = ((below > 0) | (above > 0)).any(axis=1) & finite.all(axis=1)
            if outside.any():
                self.outside_frames += 1
                self.outside_particles += int(outside.sum())
                worst = float(max(below[outside].max(), above[outside].max()))
                self.worst_outside_m = max(self.worst_outside_m, worst)
                self.first_problem = self.first_problem or f"step {m.step}: {int(outside.sum())} particles outside"
        self.total_ms.append((m.sim_time, m.step, m.timings.total_ms))
        self.particles.append(m.particle_count)
        mode = pb.GazeMode.Name(m.gaze.mode).replace("GAZE_MODE_", "").lower()
        self.gaze_modes[mode] = self.gaze_modes.get(mode, 0) + 1


def parse_args(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--duration", type=float, default=600.0, help="seconds (default 600)")
    p.add_argument("--scene", default="wave")
    p.add_argument("--method", default="gaze")
    p.add_argument("--gaze-hz", type=float, default=120.0)
    p.add_argument("--warmup", type=float, default=60.0,
                   help="memory baseline after this many seconds (default 60; shortened for short runs)")
    p.add_argument("--step-factor", type=float, default=3.0, help="slowest step allowed, times the median")
    p.add_argument("--memory-growth", type=float, default=5.0, help="allowed RSS growth, percent")
    p.add_argument("--server", help="sph_server binary (default $SPH_SERVER or build/bin/sph_server)")
    p.add_argument("--server-arg", action="append", default=[], help="extra sph_server argument (repeatable)")
    p.add_argument("--json", help="write the figures here")
    return p.parse_args(argv)


def main(argv=None) -> int:
    args = parse_args(argv)
    warmup = min(args.warmup, args.duration / 3.0)
    folder = tempfile.mkdtemp(prefix="sph_soak_")
    log_path = os.path.join(folder, "server.log")
    server = LocalServer(args.scene, method=args.method, log_path=log_path, extra_args=args.server_arg,
                         binary=args.server)
    memory = MemorySampler(server.pid)
    memory.start()
    load_summary: dict = {}
    load_thread = threading.Thread(
        target=lambda: load_summary.update(runner.run(
            single_phase(duration_s=args.duration, subscribers=1, gaze_publishers=1, gaze_hz=args.gaze_hz,
                         gaze_pattern="wandering"), server.endpoints)),
        daemon=True)
    checker = FrameChecker()
    jiffies_start = cpu_jiffies()
    started = time.monotonic()
    load_thread.start()
    decode_errors = 0
    with FrameSubscriber(server.endpoints.frames, rcvhwm=1000) as sub:
        while time.monotonic() - started < args.duration:
            data = sub.recv_bytes(0.5)
            if data is None:
                if server.process.poll() is not None:
                    break  # the server died: reported below
                continue
            message = pb.Frame()
            try:
                message.ParseFromString(data)
                frame = decode_frame(message, check_finite=False)  # NaN is counted here, not refused
            except Exception:
                decode_errors += 1
                continue
            sub.sequence.add(message.sequence)
            checker.check(frame)
        missed = sub.sequence.missed
    load_thread.join(60)
    memory.stop.set()
    memory.join(5)
    alive = server.process.poll() is None
    exit_code = server.stop()
    elapsed = time.monotonic() - started
    # Step times are wall clock: on a shared machine a preempted step reads as slow. The busy and
    # stolen CPU (a virtual machine's neighbours) of the whole machine say how shared it was.
    jiffies = [b - a for a, b in zip(jiffies_start, cpu_jiffies())]
    total_jiffies = max(1, sum(jiffies[:8]))
    idle_share = (jiffies[3] + jiffies[4]) / total_jiffies
    steal_share = jiffies[7] / total_jiffies if len(jiffies) > 7 else 0.0

    steps = [t for _, _, t in checker.total_ms]
    median_ms = statistics.median(steps) if steps else None
    slowest = sorted(checker.total_ms, key=lambda r: r[2], reverse=True)[:5]
    slow_limit = args.step_factor * median_ms if median_ms else None
    slow_steps = sum(1 for t in steps if slow_limit is not None and t > slow_limit)
    baseline = memory.median_between(warmup, warmup + MEMORY_WINDOW_S)
    end_rss = memory.median_between(elapsed - MEMORY_WINDOW_S, elapsed)
    growth = None if not baseline or end_rss is None else 100.0 * (end_rss / baseline - 1.0)
    peak = max((v for _, v in memory.samples), default=None)
    load_phase = (load_summary.get("phases") or [{}])[0]

    checks = {
        "server ran to the end and stopped cleanly": alive and exit_code == 0,
        "frames were checked": checker.frames > 0,
        "no NaN": checker.nan_frames == 0 and decode_errors == 0,
        "no particle outside the box": checker.outside_frames == 0 and checker.no_box_frames == 0,
        f"memory growth < {args.memory_growth:g} % after {warmup:.0f} s": growth is not None and growth < args.memory_growth,
        f"no step slower than {args.step_factor:g}x the median": bool(steps) and max(steps) <= args.step_factor * median_ms,
    }
    figures = {
        "scene": args.scene, "method": args.method, "duration_s": elapsed, "warmup_s": warmup,
        "frames_checked": checker.frames, "frames_missed": missed, "decode_errors": decode_errors,
        "nan_frames": checker.nan_frames, "nan_values": checker.nan_values,
        "outside_frames": checker.outside_frames, "outside_particles": checker.outside_particles,
        "worst_outside_m": checker.worst_outside_m, "frames_without_box": checker.no_box_frames,
        "particles": distribution(checker.particles),
        "rss_kib": {"after_warmup": baseline, "end": end_rss, "peak": peak, "growth_percent": growth,
                    "samples": len(memory.samples),
                    # the median of each minute: growth that levels off and growth that keeps on
                    # look alike in two numbers, not in ten
                    "by_minute": [memory.median_between(60.0 * m, 60.0 * (m + 1)) for m in range(int(elapsed // 60))]},
        "step_total_ms": distribution(steps), "slowest_steps": [
            {"sim_time": s, "step": n, "total_ms": ms} for s, n, ms in slowest],
        "slowest_over_median": (max(steps) / median_ms) if steps and median_ms else None,
        "steps_over_limit": slow_steps,
        "machine": {"cores": os.cpu_count(), "load_average_1min": distribution(memory.load),
                    "busy_share": 1.0 - idle_share, "steal_share": steal_share},
        "gaze_modes": checker.gaze_modes,
        "step_rate": load_phase.get("server", {}).get("step_rate"),
        "gaze_to_frame_ms": load_phase.get("gaze", {}).get("latency_ms"),
        "gaze_sent": load_phase.get("gaze", {}).get("sent"),
        "load_tool_cpu_percent": load_summary.get("tool_cpu", {}).get("percent_of_one_core"),
        "first_problem": checker.first_problem,
        "server_log": log_path,
        "checks_step_factor": args.step_factor,
        "checks": checks,
        "passed": all(checks.values()),
    }
    print_report(figures)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(figures, f, indent=1)
    return 0 if figures["passed"] else 1


def print_report(f: dict) -> None:
    def ms(v):
        return "-" if v is None else f"{v:.2f}"

    rss = f["rss_kib"]
    st = f["step_total_ms"]
    lat = f["gaze_to_frame_ms"] or {}
    print(f"soak: {f['scene']} / {f['method']} for {f['duration_s']:.0f} s, {f['frames_checked']} frames checked "
          f"({f['frames_missed']} missed by the checker), {f['gaze_sent']} gaze samples (wandering)")
    print(f"  particles min/median/max {f['particles']['min']:.0f}/{f['particles']['p50']:.0f}/{f['particles']['max']:.0f}; "
          f"gaze modes {f['gaze_modes']}")
    print(f"  NaN: {f['nan_frames']} frames ({f['nan_values']} values); outside the box: {f['outside_frames']} frames, "
          f"worst {f['worst_outside_m'] * 1000:.3f} mm beyond the slack")
    growth = "-" if rss["growth_percent"] is None else f"{rss['growth_percent']:+.2f} %"
    print(f"  server RSS: {rss['after_warmup']} KiB after {f['warmup_s']:.0f} s, {rss['end']} KiB at the end "
          f"({growth}), peak {rss['peak']} KiB")
    if rss["by_minute"]:
        print(f"  server RSS by minute (median KiB): {' '.join(f'{v:.0f}' for v in rss['by_minute'] if v is not None)}")
    ratio = "-" if f["slowest_over_median"] is None else f"{f['slowest_over_median']:.2f}"
    print(f"  step total_ms median {ms(st['p50'])}, p99 {ms(st['p99'])}, max {ms(st['max'])} ({ratio}x the median); "
          f"slowest at sim times {[round(s['sim_time'], 2) for s in f['slowest_steps']]}")
    print(f"  published steps over {f['checks_step_factor']:g}x the median: {f['steps_over_limit']} of {st['count']}")
    mach = f["machine"]
    load = mach["load_average_1min"]
    print(f"  machine: {mach['cores']} cores, {100 * mach['busy_share']:.0f} % busy, {100 * mach['steal_share']:.1f} % stolen, "
          f"load average p50 {load['p50']} max {load['max']}")
    rate = "-" if f["step_rate"] is None else f"{f['step_rate']:.1f}"
    print(f"  step rate {rate} steps/s; gaze-to-frame p50 {ms(lat.get('p50'))} p99 {ms(lat.get('p99'))} ms; "
          f"load tool CPU {ms(f['load_tool_cpu_percent'])} % of a core")
    for name, ok in f["checks"].items():
        print(f"  [{'PASS' if ok else 'FAIL'}] {name}")
    if f["first_problem"]:
        print(f"  first problem: {f['first_problem']}")
    print(f"soak: {'PASSED' if f['passed'] else 'FAILED'} (server log {f['server_log']})")


if __name__ == "__main__":
    sys.exit(main())
