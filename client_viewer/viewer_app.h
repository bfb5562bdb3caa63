// The window and its loop: takes the newest frame from the network thread, draws it offscreen
// (particles, outlines, gaze overlay, panel), shows it, and feeds camera pose and mouse gaze back.
#pragma once

#include <atomic>

#include "viewer_options.h"

namespace viewer {

// Set from a signal handler to close the window at the next iteration.
extern std::atomic<bool> g_stop_requested;

// Returns the process exit code: 0 done, 1 could not start (no display, no GL 3.3, bad endpoint),
// 3 --timeout reached before --frames frames arrived (a snapshot is still written), 4 snapshot
// could not be written.
int runViewer(const ViewerOptions& options);

}  // namespace viewer
