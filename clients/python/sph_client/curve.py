"""CURVE encryption and authentication for client sockets.

Keys are ZeroMQ certificate files as `zmq.auth.create_certificates` writes them and
`zmq.auth.load_certificate` reads them: DIR/NAME.key holds the public key (metadata `name`, `role`),
DIR/NAME.key_secret holds the public and the secret key. A client is given its own secret file
(`curve_secret=PATH.key_secret`) and the server's public file (`curve_server=PATH.key`).
"""

from __future__ import annotations

import contextlib
from dataclasses import dataclass
from typing import Iterator, Optional

import zmq
import zmq.auth


class CurveConfigError(ValueError):
    """A CURVE argument is missing, unreadable or of the wrong kind."""


@dataclass(frozen=True)
class ClientKeys:
    public: bytes
    secret: bytes
    server_public: bytes


def _read_certificate(path: str, what: str) -> tuple:
    try:
        return zmq.auth.load_certificate(path)
    except (OSError, ValueError) as error:
        raise CurveConfigError(f"{what} {path}: {error}") from error


def load_client_keys(curve_secret: str, curve_server: str) -> ClientKeys:
    public, secret = _read_certificate(curve_secret, "curve_secret")
    if not secret:
        raise CurveConfigError(f"curve_secret {curve_secret} holds no secret key (give the .key_secret file)")
    server_public, _ = _read_certificate(curve_server, "curve_server")
    if not server_public:
        raise CurveConfigError(f"curve_server {curve_server} holds no public key")
    return ClientKeys(public, secret, server_public)


def configure_client(socket: zmq.Socket, curve_secret: Optional[str], curve_server: Optional[str]) -> None:
    """Makes `socket` a CURVE client before it connects; does nothing when both are None.

    One without the other is an error rather than a silent plain-text connection."""
    if curve_secret is None and curve_server is None:
        return
    if curve_secret is None or curve_server is None:
        raise CurveConfigError("CURVE needs both curve_secret (yours) and curve_server (the server's public key)")
    if not zmq.has("curve"):
        raise CurveConfigError("this libzmq was built without CURVE")
    keys = load_client_keys(curve_secret, curve_server)
    socket.curve_secretkey = keys.secret
    socket.curve_publickey = keys.public
    socket.curve_serverkey = keys.server_public


@contextlib.contextmanager
def closed_on_error(socket: zmq.Socket) -> Iterator[zmq.Socket]:
    """Closes a half-configured socket when its setup raises (a bad key file, say)."""
    try:
        yield socket
    except BaseException:
        socket.close(linger=0)
        raise


@dataclass(frozen=True)
class Security:
    """The two optional CURVE paths, passed around as one value."""

    curve_secret: Optional[str] = None
    curve_server: Optional[str] = None

    @property
    def enabled(self) -> bool:
        return self.curve_secret is not None or self.curve_server is not None

    def apply(self, socket: zmq.Socket) -> None:
        configure_client(socket, self.curve_secret, self.curve_server)
