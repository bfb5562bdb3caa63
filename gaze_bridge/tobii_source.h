// Extension point for Tobii trackers. Nothing here is compiled: Tobii's Stream Engine is proprietary
// (no Debian package, a licence per device), so the bridge ships without it and `--source tobii`
// answers with an error that points here.
//
// To add it, write `class TobiiSource : public GazeSource` (gaze_source.h) in tobii_source.cpp:
//  - constructor: tobii_api_create, tobii_enumerate_local_device_urls (or a --tobii-url option),
//    tobii_device_create, tobii_gaze_point_subscribe with a callback that appends to a member queue;
//  - poll(out, timeout_ms): tobii_wait_for_callbacks (bounded by timeout_ms), then
//    tobii_device_process_callbacks; the callback turns each tobii_gaze_point_t into a TrackerSample:
//    x = position_xy[0], y = position_xy[1] (Tobii's display area is already normalized with the origin
//    top-left), valid = (validity == TOBII_VALIDITY_VALID), confidence = valid ? 1 : 0,
//    tracker_time_s = timestamp_us * 1e-6, arrival_ns = steadyNowNs();
//  - on TOBII_ERROR_CONNECTION_FAILED call tobii_device_reconnect with a back-off and report
//    connected() = false meanwhile (the same contract as the Gazepoint and Pupil sources);
//  - id() returns "tobii".
// Then build it only when the SDK is found (an option such as -DGAZE_BRIDGE_TOBII_SDK=<dir> in
// gaze_bridge/CMakeLists.txt) and let makeSource (bridge_options.cpp) construct it.
#pragma once
