"""sph_load end to end: the installed wrapper (build/bin/sph_load, $SPH_LOAD) for a few seconds
against a real sph_server on the tiny_pool scene (integration). Checks the JSON summary's shape and
that every subscriber got frames and every kind of traffic got answers; no rates are asserted."""

import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

from sph_client.local_server import LocalServer

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE_DIR = os.environ.get("SPH_TEST_SCENE_DIR") or os.path.join(HERE, "..", "..", "..", "tests", "net", "scenes")
# Without the build's wrapper, the script itself (it finds or makes the protobuf module on import).
SPH_LOAD = [os.environ["SPH_LOAD"]] if os.environ.get("SPH_LOAD") else [sys.executable, os.path.join(HERE, "..", "sph_load.py")]
RUN_TIMEOUT_S = 120  # a hang stops here; a passing run takes its scenario's seconds plus start-up

DISTRIBUTION_KEYS = {"count", "min", "p50", "p99", "max"}


class SphLoad(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.mkdtemp(prefix="sph_load_test_")
        self.addCleanup(shutil.rmtree, self.folder, ignore_errors=True)
        self.server = LocalServer("tiny_pool", method="gaze", scene_dir=SCENE_DIR,
                                  log_path=os.path.join(self.folder, "server.log"), extra_args=["--threads", "1"])
        self.addCleanup(self.server.stop)

    def run_load(self, *args):
        out = os.path.join(self.folder, "summary.json")
        e = self.server.endpoints
        command = SPH_LOAD + ["--frames-endpoint", e.frames, "--gaze-endpoint", e.gaze, "--pose-endpoint", e.pose,
                              "--control-endpoint", e.control, "--json", out, *args]
        done = subprocess.run(command, capture_output=True, text=True, timeout=RUN_TIMEOUT_S)
        self.assertEqual(done.returncode, 0, f"sph_load failed:\n{done.stdout}\n{done.stderr}\n{self.server.log()}")
        self.assertIn("sph_load itself:", done.stdout)  # the one screen of text
        with open(out) as f:
            return json.load(f)

    def check_phase(self, phase, subscribers, gaze, pose, control):
        self.assertEqual(len(phase["subscribers"]), subscribers)
        for s in phase["subscribers"]:
            self.assertGreater(s["frames"], 0, f"subscriber {s['index']} received no frame")
            self.assertGreaterEqual(s["missed"], 0)
            self.assertEqual(set(s["lag_ms"]), DISTRIBUTION_KEYS)
        self.assertTrue(phase["subscriber_totals"]["every_subscriber_received_frames"])
        self.assertEqual(set(phase["gaze"]["latency_ms"]), DISTRIBUTION_KEYS)
        if gaze:
            self.assertGreater(phase["gaze"]["sent"], 0)
            self.assertGreater(phase["gaze"]["echoed"], 0, "no frame echoed a sample of ours")
            self.assertGreater(phase["gaze"]["latency_ms"]["min"], 0.0)
            self.assertLessEqual(phase["gaze"]["latency_ms"]["p50"], phase["gaze"]["latency_ms"]["p99"])
        if pose:
            self.assertGreater(phase["pose"]["sent"], 0)
        if control:
            self.assertGreater(phase["control"]["replied"], 0)
            self.assertEqual(phase["control"]["refused"], 0)
            self.assertGreater(phase["control"]["rtt_ms"]["min"], 0.0)
        server = phase["server"]
        self.assertGreater(server["frames_observed"], 0)
        self.assertIsNotNone(server["step_rate"])
        self.assertGreater(server["step_rate"], 0.0)
        self.assertEqual(set(server["step_total_ms"]), DISTRIBUTION_KEYS)

    def check_top_level(self, summary):
        self.assertEqual(summary["tool"], "sph_load")
        self.assertEqual(summary["format"], 1)
        self.assertEqual(summary["errors"], [])
        self.assertEqual(summary["endpoints"]["frames"], self.server.endpoints.frames)
        cpu = summary["tool_cpu"]
        self.assertGreater(cpu["process_cpu_s"], 0.0)
        self.assertIn("subscriber", cpu["by_role_s"])
        self.assertIn("overall", summary)

    def test_every_kind_of_traffic_from_the_command_line(self):
        summary = self.run_load("--duration", "4", "--subscribers", "3", "--gaze-publishers", "2", "--gaze-hz", "100",
                                "--pose-hz", "30", "--control-hz", "5")
        self.check_top_level(summary)
        self.assertEqual(len(summary["phases"]), 1)
        self.check_phase(summary["phases"][0], subscribers=3, gaze=True, pose=True, control=True)

    def test_a_scenario_file_with_two_phases(self):
        scenario = {"name": "two", "phases": [
            {"name": "quiet", "duration_s": 2, "subscribers": 1},
            {"name": "busy", "duration_s": 3, "subscribers": 4, "gaze_publishers": 1, "gaze_hz": 120,
             "control_hz": 4, "control_verbs": ["status", {"verb": "set_parameters", "values": {"gaze_radius": 0.06}}]},
        ]}
        path = os.path.join(self.folder, "scenario.json")
        with open(path, "w") as f:
            json.dump(scenario, f)
        summary = self.run_load("--scenario", path)
        self.check_top_level(summary)
        self.assertEqual([p["name"] for p in summary["phases"]], ["quiet", "busy"])
        self.check_phase(summary["phases"][0], subscribers=1, gaze=False, pose=False, control=False)
        self.check_phase(summary["phases"][1], subscribers=4, gaze=True, pose=False, control=True)

    def test_a_bad_scenario_is_refused_before_any_traffic(self):
        path = os.path.join(self.folder, "bad.json")
        with open(path, "w") as f:
            json.dump({"phases": [{"subscribers": "many"}]}, f)
        done = subprocess.run(SPH_LOAD + ["--scenario", path], capture_output=True, text=True, timeout=RUN_TIMEOUT_S)
        self.assertEqual(done.returncode, 2)
        self.assertIn("phases[0].subscribers", done.stderr)


if __name__ == "__main__":
    unittest.main()
