#!/usr/bin/python3
"""Subscribe to sph_server's frames and print one line per frame.

    /usr/bin/python3 clients/python/examples/subscribe_print.py --count 5
"""

import numpy as np

from _common import parser, security
from sph_client import FINEST_LEVEL, Endpoints, FrameSubscriber, method_name, pb


def main():
    p = parser(__doc__.splitlines()[0])
    p.add_argument("--count", type=int, default=10, help="frames to print (default 10)")
    args = p.parse_args()
    endpoints = Endpoints.from_arguments(args)
    # conflate: only the newest frame, as a viewer wants; sequence gaps are then expected.
    with FrameSubscriber(endpoints.frames, conflate=True, **security(args)) as sub:
        for _ in range(args.count):
            frame = sub.recv(timeout_s=10.0)
            if frame is None:
                print(f"no frame from {endpoints.frames} in 10 s")
                return 1
            m = frame.message
            lo, hi = frame.positions.min(axis=0), frame.positions.max(axis=0)
            small = int(np.count_nonzero(frame.size_classes == FINEST_LEVEL))
            print(f"frame {m.sequence} step {m.step} t={m.sim_time:.2f}s {m.scene}/{method_name(m.method)}: "
                  f"{len(frame.positions)} particles ({small} at L0), "
                  f"x {lo[0]:.2f}..{hi[0]:.2f} y {lo[1]:.2f}..{hi[1]:.2f} z {lo[2]:.2f}..{hi[2]:.2f}, "
                  f"gaze {pb.GazeMode.Name(m.gaze.mode).replace('GAZE_MODE_', '').lower()}, "
                  f"step {m.timings.total_ms:.2f} ms")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
