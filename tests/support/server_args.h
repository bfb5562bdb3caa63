// The command line of sph_server as the tests start it, on their small scene.
#pragma once

#include <string>
#include <vector>

namespace sph_test {

// tiny_pool (tests/net/scenes), gaze method, one thread: every argument but the endpoints.
inline std::vector<std::string> tinyPoolServerArgs(const std::string& program, const std::string& scene_dir) {
  return {program, "--scene", "tiny_pool", "--scene-dir", scene_dir, "--method", "gaze", "--threads", "1"};
}

}  // namespace sph_test
