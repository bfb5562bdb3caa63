"""Starts a local sph_server on free loopback ports and reads back its endpoints (for tests, the soak
and quick experiments). The server logs lines like `endpoint frames tcp://127.0.0.1:PORT`; those
are the only way to learn a port that `tcp://127.0.0.1:*` picked.
"""

from __future__ import annotations

import os
import re
import signal
import subprocess
import time
from pathlib import Path
from typing import Optional, Sequence

from .endpoints import Endpoints

_ENDPOINT = re.compile(r"endpoint (frames|gaze|pose|control) (\S+)")


def default_server_binary() -> Path:
    """$SPH_SERVER, else build/bin/sph_server of the repository this file sits in."""
    if os.environ.get("SPH_SERVER"):
        return Path(os.environ["SPH_SERVER"])
    return Path(__file__).resolve().parents[3] / "build" / "bin" / "sph_server"


class LocalServer:
    def __init__(
        self,
        scene: str,
        *,
        method: Optional[str] = None,
        scene_dir: Optional[str] = None,
        extra_args: Sequence[str] = (),
        log_path: str,
        binary: Optional[Path] = None,
        start_timeout_s: float = 30.0,
        status_interval_s: float = 0.0,
    ):
        binary = binary or default_server_binary()
        args = [str(binary), "--scene", scene, "--status-interval", f"{status_interval_s:g}"]
        for name in ("frames", "gaze", "pose", "control"):
            args += [f"--{name}-endpoint", "tcp://127.0.0.1:*"]
        if method:
            args += ["--method", method]
        if scene_dir:
            args += ["--scene-dir", scene_dir]
        args += list(extra_args)
        self.log_path = log_path
        self._log = open(log_path, "wb")
        self.process = subprocess.Popen(args, stdout=self._log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
        self.endpoints = self._wait_for_endpoints(start_timeout_s)

    @property
    def pid(self) -> int:
        return self.process.pid

    def log(self) -> str:
        return Path(self.log_path).read_text(errors="replace")

    def _wait_for_endpoints(self, timeout_s: float) -> Endpoints:
        deadline = time.monotonic() + timeout_s
        while time.monotonic() < deadline:
            found = dict(_ENDPOINT.findall(self.log()))
            if len(found) == 4:
                return Endpoints(found["frames"], found["gaze"], found["pose"], found["control"])
            if self.process.poll() is not None:
                break
            time.sleep(0.02)
        self.stop()
        raise RuntimeError(f"sph_server did not start:\n{self.log()}")

    def stop(self, timeout_s: float = 10.0) -> Optional[int]:
        """SIGTERM (the server's clean shutdown), SIGKILL if it does not end in time; the exit code."""
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGTERM)
            try:
                self.process.wait(timeout_s)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        self._log.close()
        return self.process.returncode

    def __enter__(self) -> "LocalServer":
        return self

    def __exit__(self, *exc) -> None:
        self.stop()
