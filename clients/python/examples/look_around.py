#!/usr/bin/python3
"""Look around with gaze: send a gaze point that wanders over the screen (or circles) and watch the
server refine where it lands: the L0 particles follow the gaze. Optionally also send a camera
pose, as a viewer does, so the gaze refers to that camera.

    /usr/bin/python3 clients/python/examples/look_around.py --seconds 10 --pattern circle
"""

import time

import numpy as np

from _common import parser, security
from sph_client import FINEST_LEVEL, Endpoints, FrameSubscriber, GazePublisher, PosePublisher, gaze_patterns, pb


def main():
    p = parser(__doc__.splitlines()[0])
    p.add_argument("--seconds", type=float, default=10.0)
    p.add_argument("--hz", type=float, default=120.0, help="gaze samples per second")
    p.add_argument("--pattern", default="wandering", help="wandering, circle or fixed")
    p.add_argument("--eye", type=float, nargs=3, help="also send a camera pose from here ...")
    p.add_argument("--target", type=float, nargs=3, default=(0.0, 0.0, 0.0), help="... looking at this point")
    args = p.parse_args()
    endpoints = Endpoints.from_arguments(args)
    pattern = gaze_patterns.by_name(args.pattern)
    gaze = GazePublisher(endpoints.gaze, source_id="look_around", **security(args))
    pose = PosePublisher(endpoints.pose, viewer_id="look_around", **security(args)) if args.eye else None
    frames = FrameSubscriber(endpoints.frames, conflate=True, **security(args))
    gaze.wait_connected(5.0)
    start = time.monotonic()
    next_print = start
    try:
        while (now := time.monotonic()) - start < args.seconds:
            x, y = pattern(now - start)
            gaze.send(x, y)
            if pose is not None:
                pose.send_look_at(args.eye, args.target)
            frame = frames.recv(timeout_s=1.0 / args.hz)
            if frame is not None and now >= next_print:
                g = frame.message.gaze
                small = frame.positions[frame.size_classes == FINEST_LEVEL]
                centre = "-" if len(small) == 0 else np.array2string(small.mean(axis=0), precision=2)
                mine = "ours" if g.source_id == "look_around" else f"from {g.source_id or 'nobody'}"
                print(f"t={now - start:5.2f}s looking at ({x:.2f}, {y:.2f}); frame {frame.sequence} used "
                      f"({g.x:.2f}, {g.y:.2f}) {mine}, {pb.GazeMode.Name(g.mode).replace('GAZE_MODE_', '').lower()}: "
                      f"{len(small)} L0 particles around {centre}")
                next_print = now + 0.5
    finally:
        for s in (gaze, pose, frames):
            if s is not None:
                s.close()


if __name__ == "__main__":
    main()
