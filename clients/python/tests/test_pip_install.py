"""`pip install ./clients/python` with no package index at all (integration: a venv, pip, fresh
interpreters). The package builds with its own backend (build_backend/), and its dependencies come
from the system's site-packages (Debian's python3-zmq, -protobuf, -numpy)."""

import os
import subprocess
import sys
import tempfile
import unittest

PACKAGE_ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


class OfflineInstall(unittest.TestCase):
    def test_installs_and_runs_without_an_index(self):
        with tempfile.TemporaryDirectory() as work:
            venv = os.path.join(work, "venv")
            made = subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", venv],
                                  capture_output=True, text=True, timeout=300)
            if made.returncode != 0:
                self.skipTest(f"no venv here: {made.stderr.strip()[:200]}")
            # No index, no configuration that could name one, no cache: what a machine offline has.
            env = {**os.environ, "PIP_NO_INDEX": "1", "PIP_CONFIG_FILE": os.devnull, "PIP_NO_CACHE_DIR": "1",
                   "XDG_CACHE_HOME": os.path.join(work, "cache")}
            env.pop("SPH_PB2_DIR", None)
            pip = subprocess.run([os.path.join(venv, "bin", "python"), "-m", "pip", "install", "--no-index",
                                  PACKAGE_ROOT], capture_output=True, text=True, env=env, timeout=300)
            self.assertEqual(pip.returncode, 0, pip.stdout + pip.stderr)
            # Imported from the install (not the source tree), with the schema the wheel carries.
            probe = subprocess.run([os.path.join(venv, "bin", "python"), "-c",
                                    "import sph_client; print(sph_client.__file__); "
                                    "print(sph_client.pb.Frame.DESCRIPTOR.full_name)"],
                                   cwd=work, capture_output=True, text=True, env=env, timeout=120)
            self.assertEqual(probe.returncode, 0, probe.stderr)
            where, name = probe.stdout.split()
            self.assertTrue(where.startswith(venv), where)
            self.assertEqual(name, "gsph.v1.Frame")
            load = subprocess.run([os.path.join(venv, "bin", "sph_load"), "--version"], capture_output=True,
                                  text=True, env=env, timeout=120)
            self.assertEqual(load.returncode, 0, load.stderr)
            self.assertIn("sph_load", load.stdout)


if __name__ == "__main__":
    unittest.main()
