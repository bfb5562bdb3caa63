"""Frames from sph_server: decoding into numpy arrays, and a subscriber.

The checks mirror the viewer's decoder (client_viewer/decoded_frame.cpp): a frame whose byte
lengths disagree with particle_count, or with an unknown version or encoding, is refused as a whole
rather than drawn half right.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Optional

import numpy as np
import zmq

from . import curve
from .proto import pb

# Size levels: L0 is the finest, each level twice the mass of the one below.
FINEST_LEVEL = 0
# Deprecated aliases (the thesis's names for L0 and L1), kept for one version.
CLASS_SMALL = FINEST_LEVEL
CLASS_LARGE = 1
MAX_SIZE_LEVELS = 16  # the most levels a frame may declare in level_radii (as the viewer)
NEWEST_ONLY_QUEUE = 4  # frames a conflating FrameSubscriber's socket holds between reads (as the viewer)

_FLOAT3 = np.dtype("<f4")
_UINT16 = np.dtype("<u2")


class FrameDecodeError(ValueError):
    """The frame's bytes are not a usable gsph.v1.Frame."""


@dataclass
class DecodedFrame:
    """A checked frame. `positions` is (n, 3) float32; for FLOAT32 frames it is a read-only view of
    the message's bytes (no copy), for QUANTIZED16 frames it is computed from `quantized`, the raw
    (n, 3) uint16 view. `size_classes` is a (n,) uint8 view of each particle's size level (0: L0,
    the finest, up to the run's coarsest); `level_radii` the radius of each level in
    metres, indexed by that byte (the frame's level_radii, or (radius_small, radius_large) from a
    server that sends none); `velocities` an (n, 3) float32 view or None."""

    message: "pb.Frame"
    positions: np.ndarray
    size_classes: np.ndarray
    velocities: Optional[np.ndarray] = None
    quantized: Optional[np.ndarray] = None
    received_ns: int = 0  # time.monotonic_ns() when the bytes left the socket
    wire_bytes: int = 0
    level_radii: tuple[float, ...] = ()

    def radii(self) -> np.ndarray:
        """(n,) float32: each particle's radius in metres, from its size level."""
        return np.asarray(self.level_radii, dtype=np.float32)[self.size_classes]

    def level_counts(self) -> np.ndarray:
        """Particles per size level, L0 first, one entry per level of `level_radii` (counted from
        the particles' level bytes, so frames of servers without `level_counts` give them too)."""
        return np.bincount(self.size_classes, minlength=len(self.level_radii))

    @property
    def sequence(self) -> int:
        return self.message.sequence

    @property
    def step(self) -> int:
        return self.message.step

    def box(self) -> Optional[tuple[np.ndarray, np.ndarray]]:
        """The container (min, max) at the frame's sim time, or None when the frame has none."""
        g = self.message.geometry
        if not g.HasField("box"):
            return None
        return _vec(g.box.min), _vec(g.box.max)


def _vec(v) -> np.ndarray:
    return np.array([v.x, v.y, v.z], dtype=np.float32)


def _triples(data: bytes, dtype: np.dtype, n: int, what: str) -> np.ndarray:
    expected = n * 3 * dtype.itemsize
    if len(data) != expected:
        raise FrameDecodeError(f"{what} hold {len(data)} bytes, expected {expected} for {n} particles")
    return np.frombuffer(data, dtype=dtype).reshape(n, 3)


def _valid_radius(radius: float) -> bool:
    return math.isfinite(radius) and radius >= 0.0


def _level_radii(message: "pb.Frame") -> tuple[float, ...]:
    """The radius of every level the frame declares: level_radii, or the two thesis classes from a
    server that predates it."""
    if not all(_valid_radius(r) for r in (message.radius_small, message.radius_large)):
        raise FrameDecodeError("particle radii must be finite and non-negative")
    if not message.level_radii:
        return (message.radius_small, message.radius_large)
    if len(message.level_radii) > MAX_SIZE_LEVELS:
        raise FrameDecodeError(
            f"level_radii declares {len(message.level_radii)} size levels, at most {MAX_SIZE_LEVELS} are allowed"
        )
    for level, radius in enumerate(message.level_radii):
        if not _valid_radius(radius):
            raise FrameDecodeError(f"level_radii[{level}] must be finite and non-negative")
    return tuple(message.level_radii)


def _check_levels(classes: np.ndarray, radii: tuple[float, ...], declared: bool) -> None:
    if not len(classes) or classes.max() < len(radii):
        return
    level = int(classes.max())
    if declared:
        raise FrameDecodeError(f"size level {level} is beyond the {len(radii)} levels of level_radii")
    # Worded as before level_radii for two-class frames, so old and new clients report alike.
    raise FrameDecodeError(f"size class {level} is neither L0 (0) nor L1 (1)")


def decode_frame(message: "pb.Frame", check_finite: bool = True) -> DecodedFrame:
    """Checks and unpacks a parsed Frame; raises FrameDecodeError."""
    if message.protocol_version != pb.PROTOCOL_VERSION_CURRENT:
        raise FrameDecodeError(f"unknown protocol_version {message.protocol_version}")
    n = message.particle_count
    quantized = None
    if message.encoding == pb.POSITION_ENCODING_FLOAT32:
        positions = _triples(message.positions, _FLOAT3, n, "float32 positions")
    elif message.encoding == pb.POSITION_ENCODING_QUANTIZED16:
        quantized = _triples(message.positions, _UINT16, n, "quantized16 positions")
        if not message.HasField("quantization_box"):
            raise FrameDecodeError("quantized16 positions without a quantization_box")
        lo, hi = _vec(message.quantization_box.min), _vec(message.quantization_box.max)
        if not (np.isfinite(lo).all() and np.isfinite(hi).all() and (hi >= lo).all()):
            raise FrameDecodeError("quantization_box is not finite or has max < min")
        # value v maps to min + v / 65535 * (max - min) per axis (proto/sph.proto)
        positions = lo + quantized.astype(np.float32) * ((hi - lo) / np.float32(65535.0))
    else:
        raise FrameDecodeError(f"unknown position encoding {message.encoding}")
    if check_finite and not np.isfinite(positions).all():
        raise FrameDecodeError("a position is not finite")
    if len(message.size_classes) != n:
        raise FrameDecodeError(
            f"size_classes holds {len(message.size_classes)} bytes, expected one per particle ({n})"
        )
    classes = np.frombuffer(message.size_classes, dtype=np.uint8)
    radii = _level_radii(message)
    _check_levels(classes, radii, bool(message.level_radii))
    velocities = None
    if message.velocities:
        velocities = _triples(message.velocities, _FLOAT3, n, "velocities")
    return DecodedFrame(message, positions, classes, velocities, quantized, level_radii=radii)


def decode_frame_bytes(data: bytes, check_finite: bool = True) -> DecodedFrame:
    message = pb.Frame()
    try:
        message.ParseFromString(data)
    except Exception as error:  # protobuf raises its own DecodeError; callers need one type
        raise FrameDecodeError(f"frame bytes do not parse as gsph.v1.Frame: {error}") from error
    frame = decode_frame(message, check_finite)
    frame.wire_bytes = len(data)
    return frame


@dataclass
class SequenceTracker:
    """Counts frames and gaps in Frame.sequence (it increases by one per published frame)."""

    frames: int = 0
    gaps: int = 0  # places where at least one frame was skipped
    missed: int = 0  # frames skipped in all
    first: Optional[int] = None
    last: Optional[int] = None
    restarts: int = 0  # sequence went backwards (server restarted)

    def add(self, sequence: int) -> None:
        self.frames += 1
        if self.last is not None:
            if sequence > self.last + 1:
                self.gaps += 1
                self.missed += sequence - self.last - 1
            elif sequence <= self.last:
                self.restarts += 1
        if self.first is None:
            self.first = sequence
        self.last = sequence


class FrameSubscriber:
    """A SUB socket on the frame endpoint (subscribed to everything: frames carry no topic part).

    conflate=True keeps only the newest frame (a viewer): each read drains what is queued and
    returns the newest; False queues up to `rcvhwm` frames so every frame is seen and sequence
    gaps are real drops (a load test, a soak).
    """

    def __init__(
        self,
        endpoint: str = "tcp://127.0.0.1:5555",
        *,
        context: Optional[zmq.Context] = None,
        conflate: bool = False,
        rcvhwm: int = 100,
        curve_secret: Optional[str] = None,
        curve_server: Optional[str] = None,
    ):
        self._context = context or zmq.Context.instance()
        self.socket = self._context.socket(zmq.SUB)
        with curve.closed_on_error(self.socket):
            self.socket.setsockopt(zmq.LINGER, 0)
            # conflate: a short queue drained to its newest frame, not ZMQ_CONFLATE, whose pipe can
            # miss the wake-up for a frame that lands as the reader finds it empty (the last
            # frame of a burst then waits for the next one).
            self.socket.setsockopt(zmq.RCVHWM, NEWEST_ONLY_QUEUE if conflate else rcvhwm)
            curve.configure_client(self.socket, curve_secret, curve_server)
            self.socket.setsockopt(zmq.SUBSCRIBE, b"")
            self.socket.connect(endpoint)
        self.endpoint = endpoint
        self.newest_only = conflate
        self.sequence = SequenceTracker()
        self.rejected = 0  # frames that did not decode

    def recv_bytes(self, timeout_s: Optional[float] = None) -> Optional[bytes]:
        """The next frame's bytes, or None after timeout_s (None waits forever)."""
        if timeout_s is not None and not self.socket.poll(int(timeout_s * 1000)):
            return None
        data = self.socket.recv(copy=True)
        while self.newest_only:
            try:
                data = self.socket.recv(zmq.NOBLOCK, copy=True)
            except zmq.Again:
                break
        return data

    def recv(self, timeout_s: Optional[float] = None, decode: bool = True) -> Optional[DecodedFrame]:
        """The next frame that decodes, or None after timeout_s. decode=False skips the numpy
        unpacking and checks (positions etc. are then empty arrays; `message` is parsed)."""
        deadline = None if timeout_s is None else time.monotonic() + timeout_s
        while True:
            remaining = None if deadline is None else max(0.0, deadline - time.monotonic())
            data = self.recv_bytes(remaining)
            if data is None:
                return None
            received = time.monotonic_ns()
            try:
                if decode:
                    frame = decode_frame_bytes(data)
                else:
                    message = pb.Frame()
                    message.ParseFromString(data)
                    empty = np.empty((0, 3), np.float32)
                    frame = DecodedFrame(message, empty, np.empty(0, np.uint8), wire_bytes=len(data))
            except Exception:
                self.rejected += 1
                if deadline is not None and time.monotonic() >= deadline:
                    return None
                continue
            frame.received_ns = received
            self.sequence.add(frame.message.sequence)
            return frame

    def close(self) -> None:
        self.socket.close(linger=0)

    def __enter__(self) -> "FrameSubscriber":
        return self

    def __exit__(self, *exc) -> None:
        self.close()
