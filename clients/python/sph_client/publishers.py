"""Gaze samples and camera poses to sph_server (its gaze and pose sockets are SUB by default, so
these are PUB sockets that connect; `socket_type=zmq.PUSH` for a server started with
--gaze-socket pull / --pose-socket pull).

A PUB that has just connected drops what it sends until the connection is up (ZeroMQ's slow
joiner); `wait_connected` helps a script whose first samples matter.
"""

from __future__ import annotations

import time
from typing import Optional, Sequence

import numpy as np
import zmq
from zmq.utils.monitor import recv_monitor_message

from . import curve
from .proto import pb


def now_us() -> int:
    """The protocol's clock: microseconds of the system clock since the Unix epoch."""
    return time.time_ns() // 1000


class _Sender:
    def __init__(self, endpoint, context, socket_type, curve_secret, curve_server, sndhwm):
        self._context = context or zmq.Context.instance()
        self.socket = self._context.socket(socket_type)
        with curve.closed_on_error(self.socket):
            self.socket.setsockopt(zmq.LINGER, 0)
            self.socket.setsockopt(zmq.SNDHWM, sndhwm)
            curve.configure_client(self.socket, curve_secret, curve_server)
            self._monitor = self.socket.get_monitor_socket(zmq.EVENT_HANDSHAKE_SUCCEEDED)
            self._connected = False
            self.socket.connect(endpoint)
        self.endpoint = endpoint
        self.sent = 0
        self.sequence = 0

    def wait_connected(self, timeout_s: float = 30.0) -> bool:
        """True once the transport (and the CURVE handshake, when used) is up."""
        deadline = time.monotonic() + timeout_s
        while not self._connected and time.monotonic() < deadline:
            # Plain TCP reports HANDSHAKE_SUCCEEDED too (the ZMTP greeting is done), so one event
            # serves both kinds of connection.
            if self._monitor.poll(100) and recv_monitor_message(self._monitor)["event"] == zmq.EVENT_HANDSHAKE_SUCCEEDED:
                self._connected = True
        return self._connected

    def _send(self, message) -> None:
        self.socket.send(message.SerializeToString(), copy=False)
        self.sent += 1

    def close(self) -> None:
        self.socket.disable_monitor()
        self._monitor.close(linger=0)
        self.socket.close(linger=0)

    def __enter__(self):
        return self

    def __exit__(self, *exc) -> None:
        self.close()


class GazePublisher(_Sender):
    """Publishes GazeSample messages; `sequence` counts up from 1 and `bridge_time_us` is the send
    time, so frames that echo a sample give its gaze-to-frame latency."""

    def __init__(
        self,
        endpoint: str = "tcp://127.0.0.1:5556",
        *,
        source_id: str = "python",
        context: Optional[zmq.Context] = None,
        socket_type: int = zmq.PUB,
        curve_secret: Optional[str] = None,
        curve_server: Optional[str] = None,
        sndhwm: int = 100,
    ):
        super().__init__(endpoint, context, socket_type, curve_secret, curve_server, sndhwm)
        self.source_id = source_id

    def send(
        self,
        x: float,
        y: float,
        *,
        valid: bool = True,
        confidence: float = 1.0,
        lost: bool = False,
        fixation: bool = False,
        tracker_time_s: Optional[float] = None,
    ) -> "pb.GazeSample":
        """Sends one sample (x, y normalized 0..1, origin top left); returns it (with its sequence
        and bridge_time_us). Off-screen gaze must go as valid=False: the server rejects x, y
        outside 0..1."""
        self.sequence += 1
        sample = pb.GazeSample(
            protocol_version=pb.PROTOCOL_VERSION_CURRENT,
            source_id=self.source_id,
            sequence=self.sequence,
            tracker_time_s=time.monotonic() if tracker_time_s is None else tracker_time_s,
            bridge_time_us=now_us(),
            x=x,
            y=y,
            valid=valid,
            confidence=confidence,
            lost=lost,
            fixation=fixation,
        )
        self._send(sample)
        return sample


def look_at(eye: Sequence[float], target: Sequence[float], up: Sequence[float] = (0.0, 1.0, 0.0)) -> np.ndarray:
    """gluLookAt as a 4x4 matrix (the server's sph::lookAt)."""
    eye, target, up = (np.asarray(v, dtype=np.float64) for v in (eye, target, up))
    f = target - eye
    f /= np.linalg.norm(f)
    s = np.cross(f, up)
    s /= np.linalg.norm(s)
    u = np.cross(s, f)
    m = np.identity(4)
    m[0, :3], m[1, :3], m[2, :3] = s, u, -f
    m[:3, 3] = -m[:3, :3] @ eye
    return m


def perspective(fov_y_degrees: float, aspect: float, near: float, far: float) -> np.ndarray:
    """gluPerspective as a 4x4 matrix."""
    f = 1.0 / np.tan(np.radians(fov_y_degrees) / 2.0)
    m = np.zeros((4, 4))
    m[0, 0] = f / aspect
    m[1, 1] = f
    m[2, 2] = (far + near) / (near - far)
    m[2, 3] = 2.0 * far * near / (near - far)
    m[3, 2] = -1.0
    return m


def pose_message(view: np.ndarray, projection: np.ndarray, width: int, height: int, *, viewer_id: str,
                 sequence: int) -> "pb.CameraPose":
    """A CameraPose from 4x4 matrices (row-major numpy, as look_at returns them); the wire is
    column-major (OpenGL), so each matrix goes out transposed."""
    return pb.CameraPose(
        protocol_version=pb.PROTOCOL_VERSION_CURRENT,
        viewer_id=viewer_id,
        sequence=sequence,
        sent_time_us=now_us(),
        view=np.asarray(view, dtype=np.float64).T.reshape(16).tolist(),
        projection=np.asarray(projection, dtype=np.float64).T.reshape(16).tolist(),
        viewport_width=width,
        viewport_height=height,
    )


class PosePublisher(_Sender):
    """Publishes CameraPose messages: the camera the user's gaze refers to."""

    def __init__(
        self,
        endpoint: str = "tcp://127.0.0.1:5557",
        *,
        viewer_id: str = "python",
        context: Optional[zmq.Context] = None,
        socket_type: int = zmq.PUB,
        curve_secret: Optional[str] = None,
        curve_server: Optional[str] = None,
        sndhwm: int = 100,
    ):
        super().__init__(endpoint, context, socket_type, curve_secret, curve_server, sndhwm)
        self.viewer_id = viewer_id

    def send(self, view: np.ndarray, projection: np.ndarray, width: int, height: int) -> "pb.CameraPose":
        """view and projection: 4x4 matrices, row-major numpy (see pose_message)."""
        self.sequence += 1
        pose = pose_message(view, projection, width, height, viewer_id=self.viewer_id, sequence=self.sequence)
        self._send(pose)
        return pose

    def send_look_at(self, eye, target, up=(0.0, 1.0, 0.0), *, fov_y_degrees=45.0, width=1280, height=720,
                     near=0.05, far=20.0) -> "pb.CameraPose":
        return self.send(look_at(eye, target, up), perspective(fov_y_degrees, width / height, near, far), width,
                         height)
