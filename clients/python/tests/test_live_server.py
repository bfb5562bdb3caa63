"""sph_client against a real sph_server (integration: a child process, loopback sockets).

The server is build/bin/sph_server ($SPH_SERVER) on the small test scenes (tests/net/scenes), on
ports it picks itself. Every wait is for a condition, with a generous deadline.
"""

import os
import shutil
import tempfile
import threading
import time
import unittest

import numpy as np
import zmq

from sph_client import (
    ControlClient,
    ControlError,
    ControlTimeout,
    FrameSubscriber,
    GazePublisher,
    PosePublisher,
    pb,
)
from sph_client.local_server import LocalServer

WAIT_S = 30.0
SCENE_DIR = os.environ.get("SPH_TEST_SCENE_DIR") or os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "tests", "net", "scenes")


def start_server(test, *extra_args, method="gaze"):
    folder = tempfile.mkdtemp(prefix="sph_client_test_")
    test.addCleanup(shutil.rmtree, folder, ignore_errors=True)
    server = LocalServer("tiny_pool", method=method, scene_dir=SCENE_DIR, log_path=os.path.join(folder, "server.log"),
                         extra_args=["--threads", "1", *extra_args])
    test.addCleanup(server.stop)
    return server


def wait_frame(subscriber, predicate, what):
    deadline = time.monotonic() + WAIT_S
    while time.monotonic() < deadline:
        frame = subscriber.recv(timeout_s=0.5)
        if frame is not None and predicate(frame):
            return frame
    raise AssertionError(f"no frame {what} within {WAIT_S} s")


def inside(frame, slack=1e-4):
    lo, hi = frame.box()
    return bool(((frame.positions >= lo - slack) & (frame.positions <= hi + slack)).all())


class Frames(unittest.TestCase):
    def test_float32_then_quantized16_frames_decode_inside_the_box(self):
        server = start_server(self)
        with FrameSubscriber(server.endpoints.frames) as sub, ControlClient(server.endpoints.control,
                                                                          timeout_s=WAIT_S) as control:
            frame = wait_frame(sub, lambda f: f.message.encoding == pb.POSITION_ENCODING_FLOAT32, "in float32")
            self.assertEqual(frame.message.scene, "tiny_pool")
            self.assertEqual(frame.positions.shape, (frame.message.particle_count, 3))
            self.assertEqual(list(frame.level_counts()), list(frame.message.level_counts))
            self.assertTrue(inside(frame))
            self.assertIsNone(frame.velocities)
            control.set_parameters({"quantized": 1})
            frame = wait_frame(sub, lambda f: f.message.encoding == pb.POSITION_ENCODING_QUANTIZED16, "quantized")
            self.assertEqual(frame.quantized.shape, (frame.message.particle_count, 3))
            self.assertTrue(inside(frame, slack=1e-3))
            self.assertEqual(sub.rejected, 0)

    def test_velocities_when_the_server_sends_them(self):
        server = start_server(self, "--velocities")
        with FrameSubscriber(server.endpoints.frames, conflate=True) as sub:
            frame = wait_frame(sub, lambda f: f.velocities is not None, "with velocities")
        self.assertEqual(frame.velocities.shape, frame.positions.shape)
        self.assertTrue(np.isfinite(frame.velocities).all())


class GazeAndPose(unittest.TestCase):
    def test_frames_echo_our_gaze_sample(self):
        server = start_server(self)
        sent = {}
        with FrameSubscriber(server.endpoints.frames) as sub, GazePublisher(server.endpoints.gaze,
                                                                          source_id="py-test") as gaze:
            self.assertTrue(gaze.wait_connected(WAIT_S))
            deadline = time.monotonic() + WAIT_S
            frame = None
            while frame is None and time.monotonic() < deadline:
                sample = gaze.send(0.5, 0.5)
                sent[sample.sequence] = sample.bridge_time_us
                f = sub.recv(timeout_s=0.02)
                if f is not None and f.message.gaze.source_id == "py-test":
                    frame = f
        self.assertIsNotNone(frame, "no frame used our gaze")
        used = frame.message.gaze
        self.assertEqual(used.mode, pb.GAZE_MODE_TRACKING)
        self.assertIn(used.sample_sequence, sent)
        self.assertEqual(used.sample_bridge_time_us, sent[used.sample_sequence])
        self.assertAlmostEqual(used.x, 0.5, places=5)

    def test_frames_carry_our_camera_pose(self):
        server = start_server(self)
        with FrameSubscriber(server.endpoints.frames) as sub, PosePublisher(server.endpoints.pose,
                                                                          viewer_id="py-pose") as pose:
            deadline = time.monotonic() + WAIT_S
            frame = None
            while frame is None and time.monotonic() < deadline:
                pose.send_look_at((0.2, 1.0, 1.2), (0.2, 0.1, 0.2), width=640, height=480)
                f = sub.recv(timeout_s=0.05)
                if f is not None and f.message.camera.viewer_id == "py-pose":
                    frame = f
        self.assertIsNotNone(frame, "no frame used our pose")
        self.assertEqual((frame.message.camera.viewport_width, frame.message.camera.viewport_height), (640, 480))


class Control(unittest.TestCase):
    def test_every_verb(self):
        server = start_server(self)
        with ControlClient(server.endpoints.control, timeout_s=WAIT_S) as control, \
                FrameSubscriber(server.endpoints.frames) as sub:
            status = control.status().status
            self.assertEqual(status.scene, "tiny_pool")
            self.assertIn("tiny_column", status.scenes)
            self.assertTrue(control.pause().status.paused)
            wait_frame(sub, lambda f: f.message.paused, "paused")
            self.assertFalse(control.resume().status.paused)
            before = wait_frame(sub, lambda f: not f.message.paused and f.step > 50, "past step 50").step
            control.reset()
            wait_frame(sub, lambda f: f.step < before, "after the reset")
            self.assertEqual(control.set_method("surface").status.method, pb.METHOD_SURFACE)
            reply = control.set_parameters({"gaze_radius": 0.07})
            self.assertAlmostEqual(reply.status.parameters["gaze_radius"], 0.07)
            self.assertEqual(control.load_scene("tiny_column").status.scene, "tiny_column")
            wait_frame(sub, lambda f: f.message.scene == "tiny_column", "of the new scene")

    def test_refusals_carry_their_error_code(self):
        server = start_server(self)
        with ControlClient(server.endpoints.control, timeout_s=WAIT_S) as control:
            cases = [
                (lambda: control.load_scene("no_such_scene"), pb.ERROR_CODE_UNKNOWN_SCENE),
                (lambda: control.set_method(pb.METHOD_UNSPECIFIED), pb.ERROR_CODE_UNKNOWN_METHOD),
                (lambda: control.set_parameters({"no_such_parameter": 1.0}), pb.ERROR_CODE_BAD_PARAMETER),
                (lambda: control.set_parameters({"publish_hz": -5.0}), pb.ERROR_CODE_BAD_PARAMETER),
            ]
            for call, code in cases:
                with self.subTest(code=pb.ErrorCode.Name(code)):
                    with self.assertRaises(ControlError) as caught:
                        call()
                    self.assertEqual(caught.exception.error_code, code)
                    self.assertTrue(caught.exception.reply.error)
            reply = control.load_scene("no_such_scene", check=False)
            self.assertFalse(reply.ok)
            self.assertTrue(control.status().ok)  # still answering


class ControlTimeouts(unittest.TestCase):
    """A ROUTER in the test that answers late: the timeout fires and the late reply is not taken
    for the answer to the next request."""

    def test_timeout_then_the_late_reply_is_dropped(self):
        context = zmq.Context()
        self.addCleanup(context.destroy, 0)
        router = context.socket(zmq.ROUTER)
        self.addCleanup(router.close, 0)
        router.bind("tcp://127.0.0.1:*")
        endpoint = router.getsockopt_string(zmq.LAST_ENDPOINT)
        released = threading.Event()
        errors = []

        def answer_late():
            try:
                held = router.recv_multipart()  # request 1: held until the client has given up
                released.wait(WAIT_S)
                for parts in (held, router.recv_multipart()):
                    request = pb.Control()
                    request.ParseFromString(parts[-1])
                    reply = pb.ControlReply(protocol_version=1, request_id=request.request_id, ok=True)
                    router.send_multipart([parts[0], reply.SerializeToString()])
            except Exception as error:
                errors.append(error)

        thread = threading.Thread(target=answer_late, daemon=True)
        thread.start()
        with ControlClient(endpoint, context=context) as control:
            with self.assertRaises(ControlTimeout):
                control.status(timeout_s=0.5)
            released.set()
            reply = control.status(timeout_s=WAIT_S)
            self.assertEqual(reply.request_id, 2)
            self.assertEqual(control.stale_replies, 1)
        thread.join(WAIT_S)
        self.assertEqual(errors, [])


if __name__ == "__main__":
    unittest.main()
