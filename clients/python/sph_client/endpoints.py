"""The server's four endpoints, by host and the default ports (proto/README.md)."""

from __future__ import annotations

import argparse
from dataclasses import dataclass


@dataclass(frozen=True)
class Endpoints:
    frames: str = "tcp://127.0.0.1:5555"
    gaze: str = "tcp://127.0.0.1:5556"
    pose: str = "tcp://127.0.0.1:5557"
    control: str = "tcp://127.0.0.1:5558"

    @classmethod
    def for_host(cls, host: str, base_port: int = 5555) -> "Endpoints":
        """host as a name or an address; the ports are base_port .. base_port + 3."""
        if ":" in host and not host.startswith("["):
            host = f"[{host}]"  # an IPv6 literal
        return cls(*(f"tcp://{host}:{base_port + i}" for i in range(4)))

    @staticmethod
    def add_arguments(parser: argparse.ArgumentParser) -> None:
        """--host and one option per endpoint (an endpoint option wins over --host)."""
        parser.add_argument("--host", default="127.0.0.1", help="server host (default 127.0.0.1)")
        for name in ("frames", "gaze", "pose", "control"):
            parser.add_argument(f"--{name}-endpoint", default=None, help=f"{name} endpoint (overrides --host)")

    @classmethod
    def from_arguments(cls, args: argparse.Namespace) -> "Endpoints":
        base = cls.for_host(args.host)
        return cls(
            frames=args.frames_endpoint or base.frames,
            gaze=args.gaze_endpoint or base.gaze,
            pose=args.pose_endpoint or base.pose,
            control=args.control_endpoint or base.control,
        )
