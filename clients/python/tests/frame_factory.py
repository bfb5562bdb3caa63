"""Frames made in the test, as the server would encode them (server/net/frame_encoder.cpp)."""

import numpy as np

from sph_client import pb


def make_frame(positions, classes, *, quantized=False, box=((0, 0, 0), (1, 1, 1)), velocities=None, sequence=1,
               radius_small=0.0, radius_large=0.0, level_radii=None):
    positions = np.asarray(positions, dtype=np.float32).reshape(-1, 3)
    frame = pb.Frame(protocol_version=pb.PROTOCOL_VERSION_CURRENT, sequence=sequence, step=sequence,
                     particle_count=len(positions))
    frame.geometry.box.min.x, frame.geometry.box.min.y, frame.geometry.box.min.z = box[0]
    frame.geometry.box.max.x, frame.geometry.box.max.y, frame.geometry.box.max.z = box[1]
    if quantized:
        lo, hi = np.array(box[0], np.float32), np.array(box[1], np.float32)
        q = np.rint((positions - lo) / (hi - lo) * 65535.0).clip(0, 65535).astype("<u2")
        frame.encoding = pb.POSITION_ENCODING_QUANTIZED16
        frame.quantization_box.CopyFrom(frame.geometry.box)
        frame.positions = q.tobytes()
    else:
        frame.encoding = pb.POSITION_ENCODING_FLOAT32
        frame.positions = positions.astype("<f4").tobytes()
    frame.size_classes = bytes(classes)
    frame.radius_small, frame.radius_large = radius_small, radius_large
    if level_radii is not None:
        frame.level_radii.extend(level_radii)
    if velocities is not None:
        frame.velocities = np.asarray(velocities, dtype="<f4").tobytes()
    return frame
