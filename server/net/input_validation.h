// Untrusted input from the gaze, camera pose and control sockets: parse and check every field before
// anything reaches the simulation. Each function returns an empty string when the message is usable,
// else a short reason (for the rate-limited log), and leaves nothing half-applied.
#pragma once

#include <cstddef>
#include <string>

#include "proto/sph.pb.h"
#include "sph/camera.h"

namespace net {

inline constexpr std::size_t kMaxIdLength = 128;  // source_id, viewer_id
inline constexpr int kMaxViewportPixels = 16384;

// A gaze sample: right version; when `valid` and not `lost`, x and y finite and in 0..1 (a tracker
// looking off screen should send valid = false); confidence finite and in 0..1.
std::string parseGazeSample(const void* data, std::size_t size, gsph::v1::GazeSample& out);

// A camera pose: right version, 16 finite floats per matrix, invertible matrices, a viewport of
// 1..kMaxViewportPixels per side.
std::string parseCameraPose(const void* data, std::size_t size, gsph::v1::CameraPose& out);

// A control request: right version and a command. Parameter values and names are checked when the
// request is applied (they need the server's state), and answered with ERROR_CODE_BAD_PARAMETER.
std::string parseControl(const void* data, std::size_t size, gsph::v1::Control& out);

// Column-major (OpenGL) matrices of a checked pose as the simulation's camera, and back.
sph::ScreenCamera toScreenCamera(const gsph::v1::CameraPose& pose);
void fromScreenCamera(const sph::ScreenCamera& camera, gsph::v1::CameraPose& out);

}  // namespace net
