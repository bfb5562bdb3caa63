#!/usr/bin/python3
"""The sph_load figures of docs/performance.md: one server, loaded and unloaded, in real time and
free-running. Each run starts a fresh build/bin/sph_server on free loopback ports.

    /usr/bin/python3 clients/python/bench_load.py --duration 60 --json load_figures.json

"Loaded" is scenarios/issue17_load.json (8 subscribers, 2 gaze publishers at 200 Hz, poses at 60 Hz,
a status request every 0.5 s). "Unloaded" is one subscriber and one gaze publisher at 60 Hz: the
least traffic that still measures the step rate and keeps the gaze method tracking (with no gaze at
all the method falls back to surface refinement, which is other work, not less load).
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from sph_client.load import runner  # noqa: E402
from sph_client.load.scenario import load_scenario, single_phase  # noqa: E402
from sph_client.local_server import LocalServer  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
CLOCK_TICKS = os.sysconf("SC_CLK_TCK")


def cpu_seconds(pid: int) -> float:
    """utime + stime of a process, all threads (fields 14 and 15 of /proc/PID/stat)."""
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / CLOCK_TICKS


def machine_jiffies() -> tuple[int, int]:
    """(busy, total) jiffies of the whole machine from /proc/stat: other work on it (other users, a
    virtual machine's neighbours) moves step rates, so every run reports how busy the machine was."""
    with open("/proc/stat") as f:
        values = [int(v) for v in f.readline().split()[1:9]]
    return sum(values) - values[3] - values[4], sum(values)


def run_one(scene, method, free_run, scenario, folder, label):
    extra = ["--free-run"] if free_run else []
    with LocalServer(scene, method=method, extra_args=extra, log_path=os.path.join(folder, f"{label}.log")) as server:
        before = cpu_seconds(server.pid)
        busy0, total0 = machine_jiffies()
        summary = runner.run(scenario, server.endpoints)
        busy1, total1 = machine_jiffies()
        server_cpu = cpu_seconds(server.pid) - before
    summary["server_cpu_percent_of_one_core"] = 100.0 * server_cpu / summary["wall_s"]
    summary["machine_busy_percent"] = 100.0 * (busy1 - busy0) / max(1, total1 - total0)
    return summary


def row(label, s):
    p = s["phases"][0]
    subs = p["subscribers"]
    lat = p["gaze"]["latency_ms"]
    rtt = p["control"]["rtt_ms"]
    srv = p["server"]

    def f(v, digits=2):
        return "-" if v is None else f"{v:.{digits}f}"

    missed = "/".join(str(x["missed"]) for x in subs)
    lag = max((x["lag_ms"]["p99"] or 0.0) for x in subs)
    return (f"| {label} | {f(srv['step_rate'], 1)} | {f(srv['step_total_ms']['p50'])} / {f(srv['step_total_ms']['p99'])} | "
            f"{f(srv['particles']['p50'], 0)} | {p['subscriber_totals']['frames_min']}..{p['subscriber_totals']['frames_max']} | "
            f"{missed} | {f(lag)} | {f(lat['p50'])} / {f(lat['p99'])} (n={lat['count']}) | "
            f"{f(rtt['p50'])} / {f(rtt['p99'])} | {f(s['server_cpu_percent_of_one_core'], 0)} | "
            f"{f(s['tool_cpu']['percent_of_one_core'], 0)} | {f(s['machine_busy_percent'], 0)} |")


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--scene", default="dambreak")
    p.add_argument("--method", default="gaze")
    p.add_argument("--duration", type=float, default=60.0)
    p.add_argument("--modes", default="realtime,free-run", help="realtime, free-run or both (comma-separated)")
    p.add_argument("--json", help="write every run's sph_load summary here")
    args = p.parse_args(argv)

    loaded = load_scenario(os.path.join(HERE, "scenarios", "issue17_load.json"))
    loaded.phases[0].duration_s = args.duration
    unloaded = single_phase(duration_s=args.duration, subscribers=1, gaze_publishers=1, gaze_hz=60.0)
    folder = tempfile.mkdtemp(prefix="sph_bench_load_")
    results = {}
    lines = ["| run | steps/s | step total_ms p50 / p99 | particles | frames per subscriber | missed per subscriber | "
             "lag p99 ms | gaze-to-frame ms p50 / p99 | control RTT ms p50 / p99 | server CPU % | sph_load CPU % | machine busy % |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for mode in args.modes.split(","):
        for name, scenario in (("unloaded", unloaded), ("loaded", loaded)):
            label = f"{mode} {name}"
            print(f"bench_load: {label}, {args.duration:g} s ...", flush=True)
            results[label] = run_one(args.scene, args.method, mode == "free-run", scenario, folder,
                                     label.replace(" ", "_"))
            lines.append(row(label, results[label]))
    print(f"{args.scene} / {args.method}, {args.duration:g} s per run (server logs in {folder})")
    print("\n".join(lines))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
