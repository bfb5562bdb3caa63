// sph_viewer: the OpenGL viewer of the gaze-adaptive SPH server (docs/design.md sections 1 and 7).
#include <csignal>

#include "viewer_app.h"
#include "viewer_options.h"

namespace {
void requestStop(int /*signal*/) { viewer::g_stop_requested = true; }
}  // namespace

int main(int argc, char** argv) {
  viewer::ViewerOptions options;
  if (auto code = viewer::parseOptions(argc, argv, options)) return *code;
  std::signal(SIGINT, requestStop);
  std::signal(SIGTERM, requestStop);
  return viewer::runViewer(options);
}
