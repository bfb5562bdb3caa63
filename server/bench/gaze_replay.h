// Feeds a gaze recording to the adaptive step headless: the gaze at a simulation time is the newest
// valid sample at or before it, with its age, so the lost-gaze policy sees blinks and gaps as a
// live run would. The recording loops when the run outlasts it.
#pragma once

#include "gaze/gaze_recording.h"
#include "sph/adaptive/method.h"

namespace bench {

sph::GazeInput gazeInputAt(const gaze::GazeRecording& recording, double sim_time);

}  // namespace bench
