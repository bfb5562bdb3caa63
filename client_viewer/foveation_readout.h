// What the panel and the log say about the server's adaptive method: the real-time ratio, q and g
// (marked at the governor's ceiling), the share of the visible water over the perceptual budget,
// the particle under the gaze against the eye's acuity there, and the gaze state in the method's
// own words. Plain text from a decoded frame, no ImGui, so it is unit tested and the snapshot's
// text file holds exactly the panel's lines.
#pragma once

#include <string>
#include <vector>

#include "decoded_frame.h"

namespace viewer {

// The gaze state as the method uses it: the thesis's gaze methods fall back to surface-based
// refinement once the gaze is lost, the foveated method to a fovea at the screen's centre, and
// the regular and surface methods use no gaze.
const char* gazeStateText(gsph::v1::Method method, gsph::v1::GazeMode mode);

// The panel's lines about the method, one figure group a line.
std::vector<std::string> foveationLines(const DecodedFrame& frame);

// The same on one line, for the viewer's log.
std::string foveationLogLine(const DecodedFrame& frame);

// "L0 a, L1 b, ...": the frame's particles per level, finest first.
std::string levelCountsText(const DecodedFrame& frame);

}  // namespace viewer
