"""Python client for sph_server (wire format: proto/sph.proto, package gsph.v1).

    from sph_client import FrameSubscriber, GazePublisher, PosePublisher, ControlClient, pb

Every socket class takes optional `curve_secret=PATH.key_secret` (the client's own certificate)
and `curve_server=PATH.key` (the server's public certificate) for a CURVE-secured server.
"""

from .control import ControlClient, ControlError, ControlTimeout, build_request, method_name, method_value
from .curve import CurveConfigError, Security, configure_client, load_client_keys
from .endpoints import Endpoints
from .frames import (
    CLASS_LARGE,
    CLASS_SMALL,
    FINEST_LEVEL,
    MAX_SIZE_LEVELS,
    DecodedFrame,
    FrameDecodeError,
    FrameSubscriber,
    SequenceTracker,
    decode_frame,
    decode_frame_bytes,
)
from .proto import pb
from .publishers import GazePublisher, PosePublisher, look_at, now_us, perspective

__all__ = [
    "CLASS_LARGE",
    "CLASS_SMALL",
    "FINEST_LEVEL",
    "ControlClient",
    "ControlError",
    "ControlTimeout",
    "CurveConfigError",
    "DecodedFrame",
    "Endpoints",
    "FrameDecodeError",
    "FrameSubscriber",
    "GazePublisher",
    "MAX_SIZE_LEVELS",
    "PosePublisher",
    "Security",
    "SequenceTracker",
    "build_request",
    "configure_client",
    "decode_frame",
    "decode_frame_bytes",
    "load_client_keys",
    "look_at",
    "method_name",
    "method_value",
    "now_us",
    "pb",
    "perspective",
]

__version__ = "1.0.0"  # the project version (CMake project(VERSION), pyproject.toml); tests/cli checks they agree
