// What a frame and a status reply say about the foveated method beyond q, g and the ratio: the
// perceptual budget's counts, the particle under the gaze against the eye's acuity there, and the
// rings where the coarser levels begin, computed from the settings the last step used.
#pragma once

#include "app/sim_session.h"
#include "net/frame_encoder.h"

namespace app {

// Empty for every method but foveated. `gain_ceiling`: the most periphery gain the governor may use.
net::FoveationEcho foveationEcho(const SimSession& session, double gain_ceiling);

}  // namespace app
