"""The protobuf module made on first import when the build's copy is not given (integration: runs
protoc and fresh interpreters)."""

import os
import subprocess
import sys
import tempfile
import unittest

PACKAGE_ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
PROBE = "import sph_client; print(sph_client.pb.__file__); print(sph_client.pb.Frame.DESCRIPTOR.full_name)"


class ImportTimeGeneration(unittest.TestCase):
    def probe(self, cache):
        env = {k: v for k, v in os.environ.items() if k != "SPH_PB2_DIR"}
        env["XDG_CACHE_HOME"] = cache
        done = subprocess.run([sys.executable, "-c", PROBE], cwd=PACKAGE_ROOT, env=env, capture_output=True,
                              text=True, timeout=120)
        self.assertEqual(done.returncode, 0, done.stderr)
        return done.stdout.split()

    def test_generated_once_into_the_cache_then_reused(self):
        with tempfile.TemporaryDirectory() as cache:
            path, name = self.probe(cache)
            self.assertEqual(name, "gsph.v1.Frame")
            self.assertTrue(path.startswith(os.path.join(cache, "sph_client")), path)
            made = os.stat(path).st_mtime_ns
            again, _ = self.probe(cache)
            self.assertEqual(again, path)
            self.assertEqual(os.stat(path).st_mtime_ns, made)  # not generated a second time
            leftovers = [d for d in os.listdir(os.path.join(cache, "sph_client")) if d.startswith("gen-")]
            self.assertEqual(leftovers, [])


if __name__ == "__main__":
    unittest.main()
