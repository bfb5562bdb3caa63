"""Frame decoding (unit: no sockets): encodings, views, and every refusal the viewer's decoder makes."""

import math
import unittest

import numpy as np
import zmq

from sph_client import FrameDecodeError, FrameSubscriber, SequenceTracker, decode_frame, decode_frame_bytes, pb

from .frame_factory import make_frame

POSITIONS = [[0.1, 0.2, 0.3], [0.9, 0.5, 0.25], [0.0, 1.0, 0.5]]


class DecodeFrame(unittest.TestCase):
    def test_float32_positions_are_a_view_of_the_message_bytes(self):
        frame = make_frame(POSITIONS, [0, 1, 0])
        decoded = decode_frame_bytes(frame.SerializeToString())
        self.assertEqual(decoded.positions.shape, (3, 3))
        self.assertEqual(decoded.positions.dtype, np.float32)
        np.testing.assert_array_equal(decoded.positions, np.array(POSITIONS, np.float32))
        self.assertFalse(decoded.positions.flags.owndata)  # frombuffer: no copy
        self.assertFalse(decoded.positions.flags.writeable)
        np.testing.assert_array_equal(decoded.size_classes, [0, 1, 0])
        self.assertIsNone(decoded.velocities)
        self.assertIsNone(decoded.quantized)

    def test_quantized16_positions_follow_the_wire_formula(self):
        box = ((-1.0, 0.0, 2.0), (1.0, 0.5, 4.0))
        points = [[-1.0, 0.0, 2.0], [1.0, 0.5, 4.0], [0.25, 0.125, 3.5]]
        frame = make_frame(points, [1, 1, 0], quantized=True, box=box)
        decoded = decode_frame(frame)
        self.assertEqual(decoded.quantized.dtype, np.dtype("<u2"))
        lo, hi = np.array(box[0], np.float32), np.array(box[1], np.float32)
        expected = lo + decoded.quantized.astype(np.float32) * ((hi - lo) / np.float32(65535))
        np.testing.assert_array_equal(decoded.positions, expected)
        # One quantum of the widest axis is the most a position can move.
        np.testing.assert_allclose(decoded.positions, points, atol=2.0 / 65535)
        np.testing.assert_array_equal(decoded.quantized[0], [0, 0, 0])
        np.testing.assert_array_equal(decoded.quantized[1], [65535, 65535, 65535])

    def test_velocities_when_present(self):
        velocities = [[1, 0, 0], [0, -2, 0], [0, 0, 3]]
        decoded = decode_frame(make_frame(POSITIONS, [0, 0, 1], velocities=velocities))
        np.testing.assert_array_equal(decoded.velocities, np.array(velocities, np.float32))

    def test_empty_frame(self):
        decoded = decode_frame(make_frame(np.empty((0, 3)), []))
        self.assertEqual(decoded.positions.shape, (0, 3))
        self.assertEqual(len(decoded.size_classes), 0)

    def test_box_is_the_geometry_box(self):
        lo, hi = decode_frame(make_frame(POSITIONS, [0, 0, 0], box=((0, 0, 0), (2, 0.8, 0.8)))).box()
        np.testing.assert_array_equal(lo, [0, 0, 0])
        np.testing.assert_allclose(hi, [2, 0.8, 0.8])

    def assertRefused(self, frame, words):
        with self.assertRaises(FrameDecodeError) as caught:
            decode_frame(frame)
        self.assertIn(words, str(caught.exception))

    def test_refuses_wrong_version(self):
        frame = make_frame(POSITIONS, [0, 0, 0])
        frame.protocol_version = 2
        self.assertRefused(frame, "protocol_version")

    def test_refuses_unknown_encoding(self):
        frame = make_frame(POSITIONS, [0, 0, 0])
        frame.encoding = pb.POSITION_ENCODING_UNSPECIFIED
        self.assertRefused(frame, "encoding")

    def test_refuses_positions_of_the_wrong_length(self):
        frame = make_frame(POSITIONS, [0, 0, 0])
        frame.particle_count = 4
        self.assertRefused(frame, "float32 positions hold 36 bytes, expected 48")
        frame = make_frame(POSITIONS, [0, 0, 0], quantized=True)
        frame.positions = frame.positions[:-1]
        self.assertRefused(frame, "quantized16 positions")

    def test_refuses_quantized_without_a_sane_box(self):
        frame = make_frame(POSITIONS, [0, 0, 0], quantized=True)
        frame.ClearField("quantization_box")
        self.assertRefused(frame, "without a quantization_box")
        frame = make_frame(POSITIONS, [0, 0, 0], quantized=True)
        frame.quantization_box.max.x = -5.0
        self.assertRefused(frame, "max < min")
        frame.quantization_box.max.x = math.nan
        self.assertRefused(frame, "not finite")

    def test_refuses_non_finite_positions(self):
        frame = make_frame([[0, math.nan, 0]], [0])
        self.assertRefused(frame, "not finite")
        frame = make_frame([[math.inf, 0, 0]], [0])
        self.assertRefused(frame, "not finite")

    def test_refuses_bad_classes(self):
        self.assertRefused(make_frame(POSITIONS, [0, 1]), "size_classes holds 2 bytes")
        self.assertRefused(make_frame(POSITIONS, [0, 2, 1]), "size class 2")

    def test_size_levels_take_their_radii_from_level_radii(self):
        radii = [0.01, 0.0126, 0.0159, 0.02]
        points = [[0.1 * i, 0.1, 0.1] for i in range(6)]
        frame = make_frame(points, [0, 1, 2, 3, 3, 0], radius_small=0.01, radius_large=0.0126, level_radii=radii)
        decoded = decode_frame_bytes(frame.SerializeToString())
        np.testing.assert_array_equal(decoded.size_classes, [0, 1, 2, 3, 3, 0])
        np.testing.assert_allclose(decoded.level_radii, radii, rtol=1e-6)
        np.testing.assert_allclose(decoded.radii(), [radii[c] for c in [0, 1, 2, 3, 3, 0]], rtol=1e-6)
        np.testing.assert_array_equal(decoded.level_counts(), [2, 1, 1, 2])

    def test_two_class_frame_without_level_radii_takes_radius_small_and_large(self):
        decoded = decode_frame(make_frame(POSITIONS, [0, 1, 1], radius_small=0.04, radius_large=0.05))
        np.testing.assert_allclose(decoded.level_radii, [0.04, 0.05], rtol=1e-6)
        np.testing.assert_allclose(decoded.radii(), [0.04, 0.05, 0.05], rtol=1e-6)
        np.testing.assert_array_equal(decoded.level_counts(), [1, 2])

    def test_refuses_a_level_beyond_level_radii(self):
        self.assertRefused(make_frame(POSITIONS, [0, 3, 1], level_radii=[0.01, 0.02, 0.03]),
                           "size level 3 is beyond the 3 levels")
        self.assertRefused(make_frame(POSITIONS, [0, 2, 1]), "size class 2 is neither L0 (0) nor L1 (1)")

    def test_refuses_bad_level_radii(self):
        self.assertRefused(make_frame(POSITIONS, [0, 0, 0], level_radii=[0.01, math.nan]), "level_radii[1]")
        self.assertRefused(make_frame(POSITIONS, [0, 0, 0], level_radii=[0.01, -0.02]), "level_radii[1]")
        self.assertRefused(make_frame(POSITIONS, [0, 0, 0], level_radii=[0.01] * 17), "17 size levels")
        self.assertRefused(make_frame(POSITIONS, [0, 0, 0], radius_large=math.inf), "particle radii")
        decode_frame(make_frame(POSITIONS, [0, 15, 0], level_radii=[0.01] * 16))

    def test_refuses_velocities_of_the_wrong_length(self):
        frame = make_frame(POSITIONS, [0, 0, 0], velocities=[[1, 2, 3]])
        self.assertRefused(frame, "velocities")

    def test_refuses_bytes_that_are_not_a_frame(self):
        with self.assertRaises(FrameDecodeError):
            decode_frame_bytes(b"\xff\xff\xff\xff")


class Sequences(unittest.TestCase):
    def test_counts_gaps_and_missed_frames(self):
        tracker = SequenceTracker()
        for s in [5, 6, 7, 10, 11, 13]:
            tracker.add(s)
        self.assertEqual((tracker.frames, tracker.gaps, tracker.missed), (6, 2, 3))
        self.assertEqual((tracker.first, tracker.last), (5, 13))

    def test_a_restart_is_not_a_gap(self):
        tracker = SequenceTracker()
        for s in [100, 101, 1, 2]:
            tracker.add(s)
        self.assertEqual((tracker.gaps, tracker.restarts), (0, 1))


class NewestOnly(unittest.TestCase):
    def test_a_burst_ends_on_its_last_frame(self):
        # Over real loopback sockets: the conflating subscriber must reach the burst's last frame
        # (ZMQ_CONFLATE could leave it waiting for a frame that never comes).
        context = zmq.Context.instance()
        pub = context.socket(zmq.XPUB)
        pub.setsockopt(zmq.LINGER, 0)
        pub.bind("tcp://127.0.0.1:*")
        try:
            with FrameSubscriber(pub.getsockopt_string(zmq.LAST_ENDPOINT), conflate=True) as sub:
                self.assertTrue(pub.poll(10_000), "the subscriber should join")
                pub.recv()  # its subscription
                for sequence in range(1, 201):
                    pub.send(make_frame(POSITIONS, [0, 1, 0], sequence=sequence).SerializeToString())
                last = 0
                while last < 200:
                    frame = sub.recv(timeout_s=10.0)
                    self.assertIsNotNone(frame, f"no frame after sequence {last}")
                    self.assertGreater(frame.message.sequence, last)
                    last = frame.message.sequence
        finally:
            pub.close(linger=0)


if __name__ == "__main__":
    unittest.main()
