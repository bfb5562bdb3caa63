"""sph_load's command line (clients/python/sph_load.py and build/bin/sph_load run this)."""

from __future__ import annotations

import argparse
import re
import json
import signal
import sys
import threading

from ..curve import CurveConfigError, Security, load_client_keys
from ..endpoints import Endpoints
from . import runner
from .report import text
from .scenario import ScenarioError, load_scenario, single_phase


class _OneLineParser(argparse.ArgumentParser):
    """Usage errors as every program of the project reports them: one line on stderr, exit code 2."""

    def error(self, message):
        self.exit(2, f"{self.prog}: {message} (see {self.prog} --help)\n")


def parser() -> argparse.ArgumentParser:
    from .. import __version__

    p = _OneLineParser(
        prog="sph_load",
        epilog="Exit codes: 0 success; 1 the run saw errors; 2 usage error.",
        description="Load generator for sph_server: frame subscribers, gaze publishers, poses and control "
        "requests for a bounded time; reports drops, gaze-to-frame latency, control round trips, the "
        "server's step rate and sph_load's own CPU use.",
    )
    p.add_argument("--version", action="version", version=f"sph_load {__version__}")
    Endpoints.add_arguments(p)
    p.add_argument("--scenario", help="JSON scenario file (phases); the traffic options below are then ignored")
    p.add_argument("--duration", type=float, default=10.0, help="seconds (default 10)")
    p.add_argument("--subscribers", "-n", type=int, default=1, help="frame subscribers N (default 1)")
    p.add_argument("--gaze-publishers", "-m", type=int, default=0, help="gaze publishers M (default 0)")
    p.add_argument("--gaze-hz", "-r", type=float, default=120.0, help="samples per second per publisher R")
    p.add_argument("--gaze-pattern", default="wandering", help="wandering, circle or fixed")
    p.add_argument("--pose-hz", type=float, default=0.0, help="camera poses per second (0: none)")
    p.add_argument("--control-hz", type=float, default=0.0, help="status requests per second (0: none)")
    p.add_argument("--control-timeout", type=float, default=5.0, help="seconds before a request counts as lost")
    p.add_argument("--decode", action="store_true", help="also decode every frame into numpy arrays")
    p.add_argument("--json", metavar="PATH", help="write the JSON summary here ('-': standard output)")
    p.add_argument("--curve-secret", help="this client's certificate, PATH.key_secret")
    p.add_argument("--curve-server", help="the server's public certificate, PATH.key")
    return p


def _in_option_words(message: str) -> str:
    """A check of the command line's phase names the option a user typed, not the phase's field:
    "options.subscribers = -1: ..." -> "--subscribers -1: ..."."""
    match = re.match(r"options\.(\w+) = (.*?): (.*)", message)
    if not match:
        return message
    field, value, rule = match.groups()
    option = {"duration_s": "duration"}.get(field, field).replace("_", "-")
    return f"--{option} {value}: {rule}"


def main(argv=None) -> int:
    args = parser().parse_args(argv)
    try:
        if args.scenario:
            scenario = load_scenario(args.scenario)
        else:
            scenario = single_phase(duration_s=args.duration, subscribers=args.subscribers,
                                    gaze_publishers=args.gaze_publishers, gaze_hz=args.gaze_hz,
                                    gaze_pattern=args.gaze_pattern, pose_hz=args.pose_hz,
                                    control_hz=args.control_hz)
        security = Security(args.curve_secret, args.curve_server)
        if security.enabled:
            if not (args.curve_secret and args.curve_server):
                raise CurveConfigError("--curve-secret and --curve-server go together")
            load_client_keys(args.curve_secret, args.curve_server)  # fail now, not in eight threads
    except (ScenarioError, CurveConfigError) as error:
        print(f"sph_load: {_in_option_words(str(error))} (see sph_load --help)", file=sys.stderr)
        return 2
    stop = threading.Event()
    signal.signal(signal.SIGINT, lambda *_: stop.set())
    signal.signal(signal.SIGTERM, lambda *_: stop.set())
    summary = runner.run(scenario, Endpoints.from_arguments(args), security=security, decode=args.decode,
                         control_timeout_s=args.control_timeout, stop=stop)
    if args.json == "-":
        json.dump(summary, sys.stdout, indent=1)
        sys.stdout.write("\n")
        print(text(summary), file=sys.stderr)
    else:
        if args.json:
            with open(args.json, "w", encoding="utf-8") as f:
                json.dump(summary, f, indent=1)
        print(text(summary))
    return 1 if summary["errors"] else 0
