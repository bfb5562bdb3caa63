#!/usr/bin/python3
"""Writes the seed corpora in tests/fuzz/corpus/<target>/: a few small, valid inputs per decoder
(and a few near misses), so the fuzzer starts from the shapes real peers send instead of from
nothing. The files are committed; run this again after a change to sph.proto or a wire format (it rewrites
its own seeds and keeps the regression-* inputs, the fuzzers' past findings):

    /usr/bin/python3 tests/fuzz/make_seeds.py
"""

import os
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "clients", "python"))

import numpy as np  # noqa: E402

from sph_client import build_request, look_at, pb, perspective  # noqa: E402
from sph_client.publishers import pose_message  # noqa: E402

CORPUS = os.path.join(HERE, "corpus")


def msgpack(value) -> bytes:
    """Just enough MessagePack for Pupil's surface messages (maps, arrays, str, float, int, bool)."""
    if isinstance(value, bool):
        return b"\xc3" if value else b"\xc2"
    if isinstance(value, int):
        return struct.pack(">Bq", 0xD3, value)
    if isinstance(value, float):
        return struct.pack(">Bd", 0xCB, value)
    if isinstance(value, str):
        data = value.encode()
        return struct.pack(">BB", 0xD9, len(data)) + data
    if isinstance(value, list):
        return struct.pack(">BH", 0xDC, len(value)) + b"".join(msgpack(v) for v in value)
    if isinstance(value, dict):
        return struct.pack(">BH", 0xDE, len(value)) + b"".join(msgpack(k) + msgpack(v) for k, v in value.items())
    raise TypeError(value)


def gaze_samples():
    yield "valid", pb.GazeSample(protocol_version=1, source_id="pupil", sequence=7, tracker_time_s=12.5,
                                 bridge_time_us=1_700_000_000_000_000, x=0.4, y=0.6, valid=True, confidence=0.9,
                                 fixation=True)
    yield "lost", pb.GazeSample(protocol_version=1, source_id="gazepoint", sequence=8, lost=True, confidence=0.0)
    yield "off_screen", pb.GazeSample(protocol_version=1, source_id="mouse", x=1.5, y=-0.2, valid=False)


def camera_poses():
    view = look_at((1.0, 1.2, 2.6), (1.0, 0.1, 0.4))
    scene_camera = pose_message(view, perspective(45, 16 / 9, 0.05, 20), 1280, 720, viewer_id="viewer", sequence=3)
    singular = pose_message(np.zeros((4, 4)), np.identity(4), 800, 600, viewer_id="v", sequence=1)
    for pose in (scene_camera, singular):
        pose.sent_time_us = 1_700_000_000_000_000  # a fixed stamp: a rerun writes the same seeds
    yield "scene_camera", scene_camera
    yield "singular", singular


def controls():
    yield "status", build_request("status", 1)
    yield "pause", build_request("pause", 2)
    yield "load_scene", build_request("load_scene", 3, scene="wave")
    yield "set_method", build_request("set_method", 4, method="hybrid")
    yield "set_parameters", build_request("set_parameters", 5, values={"gaze_radius": 0.06, "publish_hz": 30})


def frames():
    rng = np.random.default_rng(1)
    positions = rng.uniform(0, 1, (6, 3)).astype("<f4")
    frame = pb.Frame(protocol_version=1, sequence=9, step=9, sim_time=0.09, scene="dambreak", method=pb.METHOD_GAZE,
                     particle_count=6, large_count=3, small_count=3, encoding=pb.POSITION_ENCODING_FLOAT32,
                     positions=positions.tobytes(), size_classes=bytes([0, 1, 0, 1, 0, 1]), radius_small=0.01,
                     radius_large=0.0126)
    frame.geometry.box.max.x, frame.geometry.box.max.y, frame.geometry.box.max.z = 1.0, 1.0, 1.0
    frame.geometry.spheres.add(radius=0.1).center.x = 0.5
    frame.geometry.cylinders.add(x=0.3, z=0.3, radius=0.05)
    frame.gaze.mode = pb.GAZE_MODE_TRACKING
    frame.gaze.x, frame.gaze.y, frame.gaze.radius, frame.gaze.ring_radius = 0.5, 0.5, 0.05, 0.08
    frame.timings.total_ms = 1.5
    yield "float32", frame
    with_velocities = pb.Frame()
    with_velocities.CopyFrom(frame)
    with_velocities.velocities = rng.normal(0, 1, (6, 3)).astype("<f4").tobytes()
    yield "velocities", with_velocities
    quantized = pb.Frame()
    quantized.CopyFrom(frame)
    quantized.encoding = pb.POSITION_ENCODING_QUANTIZED16
    quantized.quantization_box.CopyFrom(frame.geometry.box)
    quantized.positions = (positions * 65535).astype("<u2").tobytes()
    yield "quantized16", quantized
    levels = pb.Frame()
    levels.CopyFrom(frame)
    levels.method = pb.METHOD_FOVEATED
    levels.size_classes = bytes([0, 1, 2, 3, 3, 2])
    levels.level_radii.extend([0.01, 0.0126, 0.0159, 0.02])
    levels.quality, levels.realtime_ratio, levels.periphery_gain = 1.0, 0.97, 4.0
    yield "levels", levels


OPEN_GAZE = {
    "rec": b'<REC TIME="12.345" BPOGX="0.512" BPOGY="0.430" BPOGV="1" />\r\n',
    "ack_then_recs": b'<ACK ID="ENABLE_SEND_DATA" STATE="1" />\r\n<REC TIME="1.0" BPOGX="0.1" BPOGY="0.2" BPOGV="1" />\r\n'
                     b'<REC BPOGX="0.9" BPOGY="0.8" BPOGV="0" />\n',
    "split_line": b'\x05<REC TIME="2.5" BPOGX="0.25" BPOGY="0.75" BPOGV="1" />\r\n<CAL ID="CALIB_RESULT" />\r\n',
}

SCENES = [os.path.join(ROOT, "scenes", f) for f in sorted(os.listdir(os.path.join(ROOT, "scenes"))) if f.endswith(".json")]
SCENES += [os.path.join(ROOT, "tests", "net", "scenes", "tiny_pool.json")]

GAZE_RECORDINGS = {
    "plain": "time_s,x,y,valid\n0,0.5,0.5,1\n0.008333333333333333,0.5012,0.4987,1\n0.016666666666666666,2.5,-1,0\n",
    "comments": "# recorded by sph_gaze_record\n\ntime_s,x,y,valid\n# a blink follows\n0.5,0.1,0.9,1\n0.75, 0.2 ,0.8, 0\r\n1e0,+0.3,0.7,1\n",
}


def write(target, name, data: bytes):
    folder = os.path.join(CORPUS, target)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


def main():
    for name, message in gaze_samples():
        write("fuzz_gaze_sample", name, message.SerializeToString())
    for name, message in camera_poses():
        write("fuzz_camera_pose", name, message.SerializeToString())
    for name, message in controls():
        write("fuzz_control", name, message.SerializeToString())
    for name, message in frames():
        write("fuzz_viewer_frame", name, message.SerializeToString())
    for name, text in OPEN_GAZE.items():
        write("fuzz_open_gaze", name, text if text[:1] == b"\x05" else b"\x10" + text)  # first byte: piece size
    entry = {"norm_pos": [0.25, 0.75], "confidence": 0.95, "on_surf": True, "timestamp": 1234.5}
    write("fuzz_pupil_decode", "one_entry", msgpack({"name": "screen", "timestamp": 1234.5, "gaze_on_surfaces": [entry]}))
    write("fuzz_pupil_decode", "off_surface", msgpack({"gaze_on_surfaces": [
        {**entry, "on_surf": False}, {"norm_pos": [1, 0], "confidence": 1, "timestamp": 3}, {"norm_pos": [0.5]}]}))
    for path in SCENES:
        with open(path, "rb") as f:
            write("fuzz_scene_loader", os.path.basename(path), f.read())
    for name, text in GAZE_RECORDINGS.items():
        write("fuzz_gaze_recording", name + ".csv", text.encode())
    print(f"make_seeds: wrote {sum(len(files) for _, _, files in os.walk(CORPUS))} seeds into {CORPUS}")


if __name__ == "__main__":
    main()
