"""Control requests and camera matrices as they go on the wire (unit: no sockets)."""

import unittest

import numpy as np

from sph_client import build_request, look_at, method_name, method_value, pb, perspective
from sph_client.publishers import now_us, pose_message


class ControlRequests(unittest.TestCase):
    def test_every_verb_sets_its_command(self):
        cases = {
            "status": {},
            "pause": {},
            "resume": {},
            "reset": {},
            "load_scene": {"scene": "wave"},
            "set_method": {"method": "hybrid"},
            "set_parameters": {"values": {"gaze_radius": 0.07, "quantized": 1}},
        }
        for verb, arguments in cases.items():
            with self.subTest(verb=verb):
                control = build_request(verb, 42, **arguments)
                self.assertEqual(control.protocol_version, pb.PROTOCOL_VERSION_CURRENT)
                self.assertEqual(control.request_id, 42)
                self.assertEqual(control.WhichOneof("command"), verb)
                parsed = pb.Control()
                parsed.ParseFromString(control.SerializeToString())
                self.assertEqual(parsed, control)
        self.assertEqual(build_request("load_scene", 1, scene="wave").load_scene.scene, "wave")
        self.assertEqual(build_request("set_method", 1, method="hybrid").set_method.method, pb.METHOD_HYBRID)
        values = build_request("set_parameters", 1, values={"gaze_radius": 0.07}).set_parameters.values
        self.assertAlmostEqual(values["gaze_radius"], 0.07)

    def test_unknown_verbs_and_stray_arguments_are_refused(self):
        with self.assertRaises(ValueError):
            build_request("explode", 1)
        with self.assertRaises(ValueError):
            build_request("pause", 1, scene="wave")

    def test_method_names(self):
        self.assertEqual(method_value("gaze"), pb.METHOD_GAZE)
        self.assertEqual(method_value("Surface"), pb.METHOD_SURFACE)
        self.assertEqual(method_value(pb.METHOD_REGULAR), pb.METHOD_REGULAR)
        self.assertEqual(method_name(pb.METHOD_HYBRID), "hybrid")
        self.assertEqual(method_value("foveated"), pb.METHOD_FOVEATED)
        self.assertEqual(method_name(pb.METHOD_FOVEATED), "foveated")
        parsed = pb.Control()
        parsed.ParseFromString(build_request("set_method", 1, method="foveated").SerializeToString())
        self.assertEqual(method_name(parsed.set_method.method), "foveated")
        with self.assertRaises(ValueError):
            method_value("fast")


class CameraMatrices(unittest.TestCase):
    def test_look_at_maps_the_eye_to_the_origin_and_the_target_down_minus_z(self):
        eye, target = np.array([1.0, 2.0, 5.0]), np.array([1.0, 2.0, 0.0])
        view = look_at(eye, target)
        np.testing.assert_allclose(view @ np.append(eye, 1.0), [0, 0, 0, 1], atol=1e-12)
        np.testing.assert_allclose(view @ np.append(target, 1.0), [0, 0, -5, 1], atol=1e-12)

    def test_perspective_maps_near_and_far_to_the_clip_range(self):
        proj = perspective(45.0, 16 / 9, 0.1, 10.0)
        near = proj @ np.array([0, 0, -0.1, 1.0])
        far = proj @ np.array([0, 0, -10.0, 1.0])
        self.assertAlmostEqual(near[2] / near[3], -1.0)
        self.assertAlmostEqual(far[2] / far[3], 1.0)
        self.assertNotEqual(np.linalg.det(proj), 0.0)  # the server refuses a singular matrix

    def test_pose_goes_out_column_major(self):
        view = np.arange(16, dtype=np.float64).reshape(4, 4)
        pose = pose_message(view, np.identity(4), 640, 480, viewer_id="me", sequence=7)
        self.assertEqual(list(pose.view[:4]), [0.0, 4.0, 8.0, 12.0])  # the first column
        self.assertEqual((pose.viewport_width, pose.viewport_height, pose.sequence), (640, 480, 7))
        self.assertEqual(pose.protocol_version, pb.PROTOCOL_VERSION_CURRENT)

    def test_now_us_is_the_unix_epoch_in_microseconds(self):
        self.assertGreater(now_us(), 1_600_000_000 * 1_000_000)


if __name__ == "__main__":
    unittest.main()
