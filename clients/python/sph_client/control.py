"""Control requests to sph_server's ROUTER socket from a DEALER: one ControlReply per Control, the
request_id echoed. Replies to requests that timed out may still arrive later; they are recognised
by their id and dropped, so a late reply is never taken for the answer to a newer request.
"""

from __future__ import annotations

import itertools
import time
from typing import Mapping, Optional, Union

import zmq

from . import curve
from .proto import pb

METHODS = {
    "regular": pb.METHOD_REGULAR,
    "surface": pb.METHOD_SURFACE,
    "gaze": pb.METHOD_GAZE,
    "hybrid": pb.METHOD_HYBRID,
    "foveated": pb.METHOD_FOVEATED,
}


def method_value(method: Union[str, int]) -> int:
    """'gaze' or pb.METHOD_GAZE -> pb.METHOD_GAZE. Unknown names raise ValueError; numbers pass
    through unchecked so a test can send a value the server must refuse."""
    if isinstance(method, int):
        return method
    try:
        return METHODS[method.lower()]
    except KeyError:
        raise ValueError(f"unknown method {method!r} (known: {', '.join(METHODS)})") from None


def method_name(value: int) -> str:
    for name, v in METHODS.items():
        if v == value:
            return name
    return pb.Method.Name(value) if value in pb.Method.values() else str(value)


class ControlTimeout(TimeoutError):
    def __init__(self, request_id: int, timeout_s: float):
        super().__init__(f"no reply to control request {request_id} within {timeout_s} s")
        self.request_id = request_id


class ControlError(RuntimeError):
    """The server answered ok = false."""

    def __init__(self, reply: "pb.ControlReply"):
        super().__init__(f"{pb.ErrorCode.Name(reply.error_code)}: {reply.error}")
        self.reply = reply
        self.error_code = reply.error_code


def build_request(verb: str, request_id: int, **arguments) -> "pb.Control":
    """A Control message for one verb: status, pause, resume, reset, load_scene(scene=),
    set_method(method=), set_preset(preset=), set_parameters(values={name: number})."""
    control = pb.Control(protocol_version=pb.PROTOCOL_VERSION_CURRENT, request_id=request_id)
    if verb in ("status", "pause", "resume", "reset"):
        if arguments:
            raise ValueError(f"{verb} takes no arguments")
        getattr(control, verb).SetInParent()
    elif verb == "load_scene":
        control.load_scene.scene = arguments["scene"]
    elif verb == "set_method":
        control.set_method.method = method_value(arguments["method"])
    elif verb == "set_preset":
        control.set_preset.preset = arguments["preset"]
    elif verb == "set_parameters":
        values: Mapping[str, float] = arguments["values"]
        for name, value in values.items():
            control.set_parameters.values[name] = float(value)
    else:
        raise ValueError(f"unknown control verb {verb!r}")
    return control


class ControlClient:
    def __init__(
        self,
        endpoint: str = "tcp://127.0.0.1:5558",
        *,
        context: Optional[zmq.Context] = None,
        timeout_s: float = 5.0,
        curve_secret: Optional[str] = None,
        curve_server: Optional[str] = None,
    ):
        self._context = context or zmq.Context.instance()
        self.socket = self._context.socket(zmq.DEALER)
        with curve.closed_on_error(self.socket):
            self.socket.setsockopt(zmq.LINGER, 0)
            curve.configure_client(self.socket, curve_secret, curve_server)
            self.socket.connect(endpoint)
        self.endpoint = endpoint
        self.timeout_s = timeout_s
        self._ids = itertools.count(1)
        self.stale_replies = 0  # replies that arrived after their request timed out

    # The two halves of a request, for callers that keep several in flight (sph_load).
    def send(self, verb: str, **arguments) -> int:
        request_id = next(self._ids)
        self.socket.send(build_request(verb, request_id, **arguments).SerializeToString())
        return request_id

    def recv_reply(self, timeout_s: float) -> Optional["pb.ControlReply"]:
        """The next reply of any id, or None after timeout_s."""
        if not self.socket.poll(int(timeout_s * 1000)):
            return None
        parts = self.socket.recv_multipart()
        reply = pb.ControlReply()
        reply.ParseFromString(parts[-1])  # a REQ-style empty delimiter may precede the payload
        return reply

    def request(self, verb: str, *, timeout_s: Optional[float] = None, check: bool = True,
                **arguments) -> "pb.ControlReply":
        """Sends one request and waits for its reply. Raises ControlTimeout, and ControlError
        when check and the server refused."""
        timeout = self.timeout_s if timeout_s is None else timeout_s
        request_id = self.send(verb, **arguments)
        deadline = time.monotonic() + timeout
        while True:
            reply = self.recv_reply(max(0.0, deadline - time.monotonic()))
            if reply is None:
                raise ControlTimeout(request_id, timeout)
            if reply.request_id != request_id:
                self.stale_replies += 1
                continue
            if check and not reply.ok:
                raise ControlError(reply)
            return reply

    def status(self, **kw) -> "pb.ControlReply":
        return self.request("status", **kw)

    def pause(self, **kw) -> "pb.ControlReply":
        return self.request("pause", **kw)

    def resume(self, **kw) -> "pb.ControlReply":
        return self.request("resume", **kw)

    def reset(self, **kw) -> "pb.ControlReply":
        return self.request("reset", **kw)

    def load_scene(self, scene: str, **kw) -> "pb.ControlReply":
        return self.request("load_scene", scene=scene, **kw)

    def set_method(self, method: Union[str, int], **kw) -> "pb.ControlReply":
        return self.request("set_method", method=method, **kw)

    def set_preset(self, preset: str, **kw) -> "pb.ControlReply":
        """Restarts the scene with the fluid preset "thesis", "pbf" or "dfsph"."""
        return self.request("set_preset", preset=preset, **kw)

    def set_parameters(self, values: Mapping[str, float], **kw) -> "pb.ControlReply":
        return self.request("set_parameters", values=values, **kw)

    def close(self) -> None:
        self.socket.close(linger=0)

    def __enter__(self) -> "ControlClient":
        return self

    def __exit__(self, *exc) -> None:
        self.close()
