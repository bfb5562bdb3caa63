"""sph_load's results: the JSON summary (one object, format 1) and one screen of text."""

from __future__ import annotations

import collections
from dataclasses import asdict

from .records import PhaseRecord, ServerRecord, SubscriberRecord
from .scenario import Phase
from .stats import distribution, fmt_ms

FORMAT = 1


def merge(records: list) -> PhaseRecord:
    """All phases as one record (for the run's overall figures)."""
    total = PhaseRecord()
    for r in records:
        for i, s in r.subscribers.items():
            t = total.subscribers.setdefault(i, SubscriberRecord())
            for name in ("frames", "gaps", "missed", "restarts", "bytes", "rejected"):
                setattr(t, name, getattr(t, name) + getattr(s, name))
        for name in ("gaze_sent", "gaze_late"):
            merged = getattr(total, name)
            for i, n in getattr(r, name).items():
                merged[i] = merged.get(i, 0) + n
        for name in ("pose_sent", "pose_late", "control_sent", "control_replied", "control_refused",
                     "control_timeouts"):
            setattr(total, name, getattr(total, name) + getattr(r, name))
        total.server.gaze_modes.update(r.server.gaze_modes)
    for i, t in total.subscribers.items():
        t.lag_ms = t.lag_ms.merged([r.subscribers[i].lag_ms for r in records if i in r.subscribers])
    total.gaze_latency_ms = total.gaze_latency_ms.merged([r.gaze_latency_ms for r in records])
    total.control_rtt_ms = total.control_rtt_ms.merged([r.control_rtt_ms for r in records])
    server: ServerRecord = total.server
    server.steps = server.steps.merged([r.server.steps for r in records])
    for name in ("total_ms", "reported_steps_per_second", "particles"):
        setattr(server, name, getattr(server, name).merged([getattr(r.server, name) for r in records]))
    return total


def summarize(record: PhaseRecord, duration_s: float, subscribers: int, gaze_publishers: int) -> dict:
    """One phase (or the whole run) as plain JSON values. `subscribers` / `gaze_publishers`: how
    many were meant to be active, so one that received nothing still shows (with 0 frames)."""
    subs = []
    for i in range(max(subscribers, max(record.subscribers, default=-1) + 1)):
        s = record.subscribers.get(i, SubscriberRecord())
        subs.append({
            "index": i,
            "frames": s.frames,
            "frames_per_s": s.frames / duration_s if duration_s > 0 else None,
            "gaps": s.gaps,
            "missed": s.missed,
            "restarts": s.restarts,
            "rejected": s.rejected,
            "bytes": s.bytes,
            "lag_ms": distribution(s.lag_ms),
        })
    frames = [s["frames"] for s in subs]
    sent = [record.gaze_sent.get(i, 0) for i in range(gaze_publishers)]
    return {
        "duration_s": duration_s,
        "subscribers": subs,
        "subscriber_totals": {
            "count": len(subs),
            "frames_min": min(frames, default=0),
            "frames_max": max(frames, default=0),
            "gaps": sum(s["gaps"] for s in subs),
            "missed": sum(s["missed"] for s in subs),
            "every_subscriber_received_frames": bool(subs) and min(frames) > 0,
        },
        "gaze": {
            "publishers": gaze_publishers,
            "sent": sum(sent),
            "sent_per_publisher": sent,
            "rate_hz_per_publisher": [n / duration_s for n in sent] if duration_s > 0 else [],
            "late_ticks": sum(record.gaze_late.values()),
            "echoed": len(record.gaze_latency_ms),
            "latency_ms": distribution(record.gaze_latency_ms),
        },
        "pose": {
            "sent": record.pose_sent,
            "rate_hz": record.pose_sent / duration_s if duration_s > 0 else None,
            "late_ticks": record.pose_late,
        },
        "control": {
            "sent": record.control_sent,
            "replied": record.control_replied,
            "refused": record.control_refused,
            "timeouts": record.control_timeouts,
            "rtt_ms": distribution(record.control_rtt_ms),
        },
        "server": {
            "frames_observed": record.server.steps.frames,
            "step_rate": record.server.steps.rate,
            "reported_steps_per_second": distribution(record.server.reported_steps_per_second),
            "step_total_ms": distribution(record.server.total_ms),
            "particles": distribution(record.server.particles),
            "gaze_modes": dict(collections.Counter(record.server.gaze_modes)),
        },
    }


def phase_summary(phase, record: PhaseRecord) -> dict:
    summary = summarize(record, phase.duration_s, phase.subscribers, phase.gaze_publishers)
    return {"name": phase.name, "config": asdict(phase), **summary}


def _dist(d: dict) -> str:
    return f"p50 {fmt_ms(d['p50'])} p99 {fmt_ms(d['p99'])} max {fmt_ms(d['max'])} ms (n={d['count']})"


def phase_text(name: str, describe: str, s: dict) -> list:
    subs = s["subscribers"]
    totals = s["subscriber_totals"]
    lines = [f"phase {name!r} {s['duration_s']:.1f} s: {describe}"]
    per_sub = " ".join(f"{x['index']}:{x['frames']}/{x['missed']}" for x in subs)
    lines.append(f"  frames per subscriber (received/missed): {per_sub or '-'}")
    lines.append(f"  sequence gaps {totals['gaps']} ({totals['missed']} frames missed); "
                 f"subscribers with no frame: {sum(1 for x in subs if x['frames'] == 0)}")
    lags = [x["lag_ms"]["p99"] for x in subs if x["lag_ms"]["p99"] is not None]
    if lags:
        lines.append(f"  receive lag (arrival - send_time_us) worst subscriber p99 {max(lags):.2f} ms")
    g = s["gaze"]
    if g["publishers"]:
        rates = "/".join(f"{r:.0f}" for r in g["rate_hz_per_publisher"])
        lines.append(f"  gaze: {g['sent']} sent ({rates} Hz), {g['late_ticks']} late ticks; "
                     f"gaze-to-frame {_dist(g['latency_ms'])}")
    if s["pose"]["sent"]:
        lines.append(f"  pose: {s['pose']['sent']} sent ({s['pose']['rate_hz']:.1f} Hz)")
    c = s["control"]
    if c["sent"]:
        lines.append(f"  control: {c['sent']} sent, {c['replied']} replied, {c['refused']} refused, "
                     f"{c['timeouts']} timeouts; round trip {_dist(c['rtt_ms'])}")
    srv = s["server"]
    rate = "-" if srv["step_rate"] is None else f"{srv['step_rate']:.1f}"
    lines.append(f"  server: {rate} steps/s from frames' steps over send_time_us; step total_ms "
                 f"{_dist(srv['step_total_ms'])}")
    if srv["particles"]["count"]:
        modes = ", ".join(f"{k.replace('GAZE_MODE_', '').lower()} {v}" for k, v in sorted(srv["gaze_modes"].items()))
        lines.append(f"  particles p50 {srv['particles']['p50']:.0f}; gaze modes: {modes}")
    return lines


def text(summary: dict) -> str:
    lines = [f"sph_load: {summary['wall_s']:.1f} s against {summary['endpoints']['frames']}"
             f"{' (CURVE)' if summary['curve'] else ''}, scenario {summary['scenario']['name']!r}"]
    for p in summary["phases"]:
        lines += phase_text(p["name"], Phase(**p["config"]).describe(), p)
    if len(summary["phases"]) > 1:
        lines += phase_text("overall", "all phases", summary["overall"])
    cpu = summary["tool_cpu"]
    roles = ", ".join(f"{k} {v:.1f} s" for k, v in sorted(cpu["by_role_s"].items()))
    lines.append(f"sph_load itself: {cpu['process_cpu_s']:.1f} CPU s in {cpu['wall_s']:.1f} s = "
                 f"{cpu['percent_of_one_core']:.0f} % of one core ({cpu['machine_cores']} cores here); {roles}")
    for error in summary["errors"]:
        lines.append(f"ERROR {error}")
    return "\n".join(lines)
