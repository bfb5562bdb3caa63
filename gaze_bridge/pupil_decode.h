// Pupil Capture's surface-mapped gaze (Surface Tracker plugin, topic "surfaces.<name>"): a msgpack map
//   { "name": ..., "timestamp": ..., "gaze_on_surfaces": [ { "norm_pos": [x, y], "confidence": c,
//     "on_surf": true, "timestamp": t, ... }, ... ], ... }
// norm_pos has its origin at the surface's bottom-left, so y is flipped to the bridge's top-left.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "tracker_sample.h"

namespace gaze_bridge {

// Appends one TrackerSample per entry of gaze_on_surfaces (on_surf false -> valid false). Returns an
// empty string on success, else why the payload was rejected (nothing appended then). Entries that are
// malformed on their own are skipped and counted in `skipped`.
std::string decodePupilSurfaceMessage(const void* data, std::size_t size, std::int64_t arrival_ns,
                                      std::vector<TrackerSample>& out, std::size_t& skipped);

}  // namespace gaze_bridge
