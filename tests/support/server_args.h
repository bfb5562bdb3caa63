// The command line of sph_server as the tests start it, on their small scene.
#pragma once

#include <string>
#include <vector>

namespace sph_test {

// Tests of the wire, the viewer and recovery count frames and refinements over time; they run the
// thesis preset, whose step is the cheapest, so that a slow or busy machine still publishes enough
// frames within their deadlines. The fluids' own tests (tests/sph, the scenario tier) cover pbf and
// dfsph, and the binary tests check sph_server's default.
inline const std::vector<std::string> kCheapPreset = {"--preset", "thesis"};

// tiny_pool (tests/net/scenes), gaze method, one thread: every argument but the endpoints.
inline std::vector<std::string> tinyPoolServerArgs(const std::string& program, const std::string& scene_dir) {
  return {program, "--scene", "tiny_pool", "--scene-dir", scene_dir, "--method", "gaze", "--threads", "1"};
}

}  // namespace sph_test
