"""Command-line conventions of every program (README "Exit codes"): --version and --help on stdout
with exit code 0; a usage error is one line on stderr naming the option (and the accepted values),
exit code 2, nothing on stdout; logs go to stderr, stdout carries only data and reports.

Run by ctest (tests/cli/CMakeLists.txt) with SPH_BIN_DIR = the build's bin/ and SPH_SOURCE_DIR."""

import contextlib
import json
import os
import select
import shutil
import signal
import socket
import subprocess
import tempfile
import unittest

BIN = os.environ["SPH_BIN_DIR"]
SOURCE = os.environ["SPH_SOURCE_DIR"]
VERSION = os.environ["SPH_VERSION"]
PROGRAMS = ["sph_server", "sph_bench", "sph_validate", "sph_gaze_record", "sph_keygen", "sph_relay", "gaze_bridge", "sph_viewer",
            "sph_load"]
# No display from the caller: the one case that opens a window starts its own (virtual_display).
ENV = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
DEADLINE_S = 120  # a hang, not a speed limit


def run(program, *args, **kwargs):
    return subprocess.run([os.path.join(BIN, program), *args], capture_output=True, text=True, env=ENV,
                          timeout=DEADLINE_S, **kwargs)


@contextlib.contextmanager
def virtual_display():
    """An Xvfb of our own, as the window tests start it (tests/viewer/child_process.cpp): -displayfd
    picks a free display, so parallel tests never race for one. Not xvfb-run: its clean-up can fail
    after the program under test has exited and then replaces that program's exit code with 5."""
    read_end, write_end = os.pipe()
    xvfb = subprocess.Popen(["Xvfb", "-displayfd", str(write_end), "-screen", "0", "1280x1024x24", "-nolisten", "tcp",
                             "-noreset"], pass_fds=(write_end,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write_end)
    try:
        # Xvfb writes the display number and a newline once it accepts connections.
        number = b""
        while not number.endswith(b"\n") and select.select([read_end], [], [], DEADLINE_S)[0]:
            chunk = os.read(read_end, 16)
            if not chunk:
                break
            number += chunk
        if not number.endswith(b"\n"):
            raise RuntimeError("Xvfb did not report a display")
        yield f":{int(number)}"
    finally:
        os.close(read_end)
        xvfb.terminate()
        xvfb.wait(timeout=DEADLINE_S)


def any_port_endpoint():
    return "tcp://127.0.0.1:*"  # the server picks a free port and logs it


class VersionAndHelp(unittest.TestCase):
    def test_version_on_stdout(self):
        for program in PROGRAMS:
            with self.subTest(program=program):
                r = run(program, "--version")
                self.assertEqual(r.returncode, 0, r.stderr)
                self.assertEqual(r.stdout.strip(), f"{program} {VERSION}")
                self.assertEqual(r.stderr, "")

    def test_help_on_stdout_documents_exit_codes(self):
        for program in PROGRAMS:
            with self.subTest(program=program):
                r = run(program, "--help")
                self.assertEqual(r.returncode, 0, r.stderr)
                self.assertIn("Exit codes: 0", r.stdout)
                self.assertIn("2 usage error", r.stdout)
                self.assertEqual(r.stderr, "")
                # CLI11's internal notation must not reach a user.
                self.assertNotIn("{false}", r.stdout)
                self.assertNotIn("->0", r.stdout)


class ServerHelp(unittest.TestCase):
    def test_options_come_in_groups(self):
        r = run("sph_server", "--help")
        self.assertEqual(r.returncode, 0, r.stderr)
        headings = [line for line in r.stdout.splitlines() if line.endswith(":") and not line.startswith(" ")]
        for group in ("Scene and physics:", "Run and frames:", "Network:", "Gaze and adaptivity:", "Security:",
                      "Logging:"):
            self.assertIn(group, headings)
        # The simulation parameters and the adaptive settings come from the settings table (sph/param_table.h).
        self.assertIn("pbf_iterations", r.stdout)
        self.assertIn("foveated_thin_level", r.stdout)


class UsageErrors(unittest.TestCase):
    def assert_usage_error(self, program, args, *expected):
        r = run(program, *args)
        self.assertEqual(r.returncode, 2, f"{program} {args}: {r.stdout} {r.stderr}")
        self.assertEqual(r.stdout, "", f"{program} {args}")
        lines = r.stderr.splitlines()
        self.assertEqual(len(lines), 1, f"{program} {args}: {r.stderr!r}")
        self.assertTrue(lines[0].startswith(program + ": "), lines[0])
        for word in expected:
            self.assertIn(word, lines[0])
        for internal in ("stod", "CLI", "0.000000", "terminate", "what()"):
            self.assertNotIn(internal, lines[0])
        return lines[0]

    def test_unknown_option(self):
        for program in PROGRAMS:
            with self.subTest(program=program):
                # sph_keygen checks its required NAME first: give it one.
                self.assert_usage_error(program, (["k"] if program == "sph_keygen" else []) + ["--bogus"], "--bogus")

    def test_missing_value(self):
        for program, option in [("sph_server", "--scene"), ("sph_bench", "--scene"), ("sph_gaze_record", "--scene"),
                                ("sph_keygen", "--role"), ("sph_relay", "--upstream"), ("gaze_bridge", "--source"),
                                ("sph_viewer", "--frames-endpoint"), ("sph_load", "--duration")]:
            with self.subTest(program=program):
                self.assert_usage_error(program, [option], option)

    def test_bad_values_name_the_accepted_ones(self):
        self.assert_usage_error("sph_server", ["--method", "fast"], "--method", "fast", "regular", "hybrid")
        self.assert_usage_error("sph_server", ["--threads", "abc"], "--threads", "1 to 256")
        self.assert_usage_error("sph_server", ["--publish-hz", "abc"], "--publish-hz", "abc")
        self.assert_usage_error("sph_bench", ["--export-format", "obj"], "--export-format", "vtu")
        self.assert_usage_error("sph_server", ["--preset", "water"], "--preset", "water", "pbf", "dfsph", "thesis")
        self.assert_usage_error("sph_bench", ["--preset", "water"], "--preset", "water", "pbf", "dfsph", "thesis")
        self.assert_usage_error("sph_bench", ["--preset", "pbf,dfsph,pbf"], "--preset", "pbf", "twice")
        self.assert_usage_error("sph_validate", ["--preset", "water"], "--preset", "water", "pbf")
        self.assert_usage_error("sph_viewer", ["--render", "ascii"], "--render", "fluid", "particles")
        self.assert_usage_error("sph_viewer", ["--fov", "abc"], "--fov", "5 to 150")
        self.assert_usage_error("gaze_bridge", ["--min-confidence", "2"], "--min-confidence", "0 to 1")
        self.assert_usage_error("sph_relay", ["--hwm", "0"], "--hwm", "1 to 100000")

    def test_out_of_range_numbers_and_names_in_a_short_line(self):
        for program, args, words in [
                ("sph_bench", ["--frames", "-5"], ["--frames", ">= 0", "-5"]),
                ("sph_bench", ["--interleave", "-1"], ["--interleave", ">= 0"]),
                ("sph_bench", ["--export-every", "-1"], ["--export-every", ">= 0"]),
                ("sph_bench", ["--method", "nosuch"], ["--method", "nosuch", "regular", "hybrid"]),
                ("gaze_bridge", ["--duration", "-1"], ["--duration", ">= 0"]),
                ("sph_viewer", ["--render", "nosuch"], ["--render", "'nosuch' is not one of fluid, particles"]),
                ("sph_keygen", ["--frobnicate"], ["unknown option", "--frobnicate"]),
                ("sph_load", ["-n", "-1"], ["--subscribers", "0..256"]),
                ("sph_server", ["--param", "pbf_omega=2"], ["--param", "pbf_omega", "(0, 1]"]),
                ("sph_server", ["--param", "nosuch=1"], ["--param", "nosuch"])]:
            with self.subTest(program=program, args=args):
                line = self.assert_usage_error(program, args, *words)
                self.assertLess(len(line), 200, line)
                self.assertNotIn("Check", line)
                self.assertNotIn("options.", line)

    def test_adaptive_settings(self):
        self.assert_usage_error("sph_server", ["--adaptive", "alpha=x"], "--adaptive", "alpha=x", "number")
        self.assert_usage_error("sph_server", ["--adaptive", "nosuch=1"], "unknown setting 'nosuch'", "--help")
        # One table: either option takes any setting, in the table's wording.
        self.assert_usage_error("sph_server", ["--adaptive", "foveated_thin_level=1.5"], "foveated_thin_level",
                                "must be an integer in [0, 7]")
        self.assert_usage_error("sph_server", ["--param", "gaze_radius=3"], "gaze_radius", "[0, 2]")

    def test_options_that_do_not_go_together(self):
        self.assert_usage_error("gaze_bridge", ["--source", "replay"], "--replay")
        self.assert_usage_error("sph_viewer", ["--eye", "0", "0", "1"], "--eye", "--target")


class StreamsAndExitCodes(unittest.TestCase):
    def test_server_logs_on_stderr_only(self):
        endpoints = []
        for name in ("frames", "gaze", "pose", "control"):
            endpoints += [f"--{name}-endpoint", any_port_endpoint()]
        r = run("sph_server", "--scene", "small_box", "--free-run", "--max-steps", "2", "--status-interval", "0",
                *endpoints)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stdout, "")
        self.assertIn("endpoint frames tcp://127.0.0.1:", r.stderr)

    def test_server_runtime_failure_is_1(self):
        r = run("sph_server", "--scene", "nosuch", "--max-steps", "1")
        self.assertEqual(r.returncode, 1)
        self.assertEqual(r.stdout, "")
        self.assertIn("nosuch", r.stderr)

    def test_bridge_logs_on_stderr_only(self):
        r = run("gaze_bridge", "--source", "synthetic", "--duration", "0.3", "--endpoint", "tcp://127.0.0.1:1")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stdout, "")
        self.assertIn("stopped", r.stderr)

    def test_bridge_tracker_that_never_connects_is_3(self):
        with socket.socket() as held:  # bound, never listening: connections are refused
            held.bind(("127.0.0.1", 0))
            port = held.getsockname()[1]
            r = run("gaze_bridge", "--source", "gazepoint", "--gazepoint-host", "127.0.0.1", "--gazepoint-port",
                    str(port), "--duration", "1", "--endpoint", "tcp://127.0.0.1:1")
        self.assertEqual(r.returncode, 3, r.stderr)
        self.assertEqual(r.stdout, "")
        self.assertIn("never sent a sample", r.stderr)

    def test_keygen_report_on_stdout_refusal_on_stderr(self):
        with tempfile.TemporaryDirectory() as out:
            r = run("sph_keygen", "alice", "--role", "viewer", "--out", out)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("wrote", r.stdout)
            self.assertEqual(r.stderr, "")
            again = run("sph_keygen", "alice", "--out", out)  # never overwrites a key: a failed run
            self.assertEqual(again.returncode, 1)
            self.assertEqual(again.stdout, "")
            self.assertIn("sph_keygen:", again.stderr)

    def test_relay_logs_on_stderr_and_stops_on_sigterm(self):
        relay = subprocess.Popen([os.path.join(BIN, "sph_relay"), "--upstream", "tcp://127.0.0.1:1", "--endpoint",
                                  any_port_endpoint(), "--status-interval", "0"], stdout=subprocess.PIPE,
                                 stderr=subprocess.PIPE, text=True, env=ENV)
        first = relay.stderr.readline()  # it is up once it has logged its endpoint
        self.assertIn("endpoint relay", first)
        relay.send_signal(signal.SIGTERM)
        out, err = relay.communicate(timeout=DEADLINE_S)
        self.assertEqual(relay.returncode, 0, err)
        self.assertEqual(out, "")
        self.assertIn("SIGTERM received", err)

    def test_bench_report_on_stdout_progress_on_stderr(self):
        with tempfile.TemporaryDirectory() as out:
            r = run("sph_bench", "--scene", "small_box", "--frames", "2", "--out", out)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("small_box/", r.stdout)
            self.assertIn("(pbf)", r.stdout, "sph_bench runs pbf unless told otherwise, as sph_server does")
            self.assertNotIn("frame 1/2", r.stdout)
            self.assertIn("frame", r.stderr)
            self.assertTrue(os.path.exists(os.path.join(out, "frames.csv")))

    def test_bench_interrupted_keeps_its_rows(self):
        with tempfile.TemporaryDirectory() as out:
            bench = subprocess.Popen([os.path.join(BIN, "sph_bench"), "--scene", "small_box", "--frames", "100000",
                                      "--out", out], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                     env=ENV)
            # The first progress line comes after the first frame: wait for it, then Ctrl-C.
            first = bench.stderr.readline()
            self.assertIn("frame", first)
            bench.send_signal(signal.SIGINT)
            report, err = bench.communicate(timeout=DEADLINE_S)
            self.assertEqual(bench.returncode, 130, err)
            self.assertIn("interrupted", err)
            self.assertIn(out, err)
            with open(os.path.join(out, "frames.csv"), encoding="utf-8") as f:
                rows = f.read().splitlines()
            self.assertGreaterEqual(len(rows), 2)  # the header and at least the first frame
            # The summary says what was run, not what was asked: a partial run never passes for a whole one.
            with open(os.path.join(out, "summary.json"), encoding="utf-8") as f:
                summary = json.load(f)
            self.assertTrue(summary["interrupted"])
            self.assertEqual(summary["frames_asked"], 100000)
            self.assertEqual(summary["frames"], len(rows) - 1)
            self.assertIn("of 100000 frames (INTERRUPTED)", report)

    def test_viewer_without_server_names_the_endpoint_and_exits_3(self):
        if shutil.which("Xvfb") is None:
            self.skipTest("Xvfb not installed")
        # --timeout, and --duration (what the main command uses headless): both say where they waited.
        for limit in (["--timeout", "1"], ["--duration", "1"]):
            with self.subTest(limit=limit[0]), socket.socket() as held, tempfile.TemporaryDirectory() as out, \
                    virtual_display() as display:
                held.bind(("127.0.0.1", 0))
                endpoint = f"tcp://127.0.0.1:{held.getsockname()[1]}"
                r = subprocess.run([os.path.join(BIN, "sph_viewer"), "--frames-endpoint", endpoint, "--snapshot",
                                    os.path.join(out, "x.png"), *limit, "--width", "160", "--height", "120"],
                                   capture_output=True, text=True, env={**ENV, "DISPLAY": display}, timeout=DEADLINE_S)
                self.assertEqual(r.returncode, 3, r.stderr)
                self.assertIn(f"waiting for frames from {endpoint}", r.stderr)
                self.assertIn(f"no frame from a server at {endpoint}", r.stderr)
                self.assertEqual(r.stdout, "")
                self.assertFalse(os.path.exists(os.path.join(out, "x.png")), "a picture without water was written")


class MainCommand(unittest.TestCase):
    """The parts of scripts/run_main.sh that come before it installs or builds anything."""

    def main_command(self, *args):
        return subprocess.run(["bash", os.path.join(SOURCE, "scripts", "run_main.sh"), *args], capture_output=True,
                              text=True, timeout=DEADLINE_S)

    def test_help_prints_help_only(self):
        r = self.main_command("--help")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("--scene NAME", r.stdout)
        self.assertNotIn("sed ", r.stdout)
        self.assertNotIn("set -euo", r.stdout)
        self.assertNotIn("esac", r.stdout)

    def test_missing_value_is_a_clear_error(self):
        for option in ("--scene", "--method", "--seconds", "--bridge", "--out"):
            with self.subTest(option=option):
                r = self.main_command(option)
                self.assertEqual(r.returncode, 2, r.stderr)
                self.assertEqual(r.stderr.splitlines(), [f"run_main: {option} needs a value (see bash "
                                                         "scripts/run_main.sh --help)"])
                self.assertNotIn("unbound", r.stderr)

    def test_bad_values(self):
        r = self.main_command("--method", "fast")
        self.assertEqual(r.returncode, 2)
        self.assertIn("regular, surface, gaze, hybrid or foveated", r.stderr)
        r = self.main_command("--scene", "nosuch")
        self.assertEqual(r.returncode, 2)
        self.assertIn("dambreak", r.stderr)


if __name__ == "__main__":
    unittest.main()
