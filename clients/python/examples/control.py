#!/usr/bin/python3
"""Control sph_server: one request, its reply printed.

    /usr/bin/python3 clients/python/examples/control.py status
    /usr/bin/python3 clients/python/examples/control.py pause
    /usr/bin/python3 clients/python/examples/control.py resume
    /usr/bin/python3 clients/python/examples/control.py reset
    /usr/bin/python3 clients/python/examples/control.py load_scene wave
    /usr/bin/python3 clients/python/examples/control.py set_method hybrid
    /usr/bin/python3 clients/python/examples/control.py set_parameters gaze_radius=0.06 publish_hz=30
"""

import sys

from _common import parser, security
from sph_client import ControlClient, ControlError, ControlTimeout, Endpoints, method_name


def level_text(status) -> str:
    """ "L0 a, L1 b, ...": the status's level_counts, or the deprecated two counts of an older server."""
    counts = list(status.level_counts) or [status.small_count, status.large_count]
    return ", ".join(f"L{k} {n}" for k, n in enumerate(counts))


def arguments_for(verb, rest):
    if verb == "load_scene":
        return {"scene": rest[0]}
    if verb == "set_method":
        return {"method": rest[0]}
    if verb == "set_preset":
        return {"preset": rest[0]}
    if verb == "set_parameters":
        return {"values": {k: float(v) for k, v in (item.split("=", 1) for item in rest)}}
    return {}


def main():
    p = parser(__doc__.splitlines()[0])
    p.add_argument("verb", choices=["status", "pause", "resume", "reset", "load_scene", "set_method",
                                    "set_preset", "set_parameters"])
    p.add_argument("values", nargs="*", help="scene name, method, preset, or NAME=VALUE pairs")
    p.add_argument("--timeout", type=float, default=5.0)
    args = p.parse_args()
    try:
        arguments = arguments_for(args.verb, args.values)
    except (IndexError, ValueError) as error:
        # A missing value, NAME=VALUE that is not one, an unknown method name: the client's own check.
        p.error(f"{args.verb}: {error}" if str(error) else f"{args.verb} needs a value")
    with ControlClient(Endpoints.from_arguments(args).control, timeout_s=args.timeout, **security(args)) as control:
        try:
            reply = control.request(args.verb, **arguments)
        except ValueError as error:
            p.error(f"{args.verb}: {error}")
        except ControlTimeout as error:
            print(error, file=sys.stderr)
            return 1
        except ControlError as error:
            print(f"refused: {error}", file=sys.stderr)
            return 1
    s = reply.status
    print(f"ok (request {reply.request_id}): {s.scene} / {s.preset} / {method_name(s.method)}, {'paused' if s.paused else 'running'}, "
          f"step {s.step}, {s.steps_per_second:.1f} steps/s, {s.particle_count} particles "
          f"({level_text(s)}), {s.subscribers} subscribers, gaze age {s.gaze_age_ms:.0f} ms")
    print(f"   scenes: {', '.join(s.scenes)}")
    print(f"   parameters: {', '.join(f'{k}={v:g}' for k, v in sorted(s.parameters.items()))}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
