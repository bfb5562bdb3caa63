// The on-screen panel (Dear ImGui): what the server and this viewer are doing, and buttons that send
// Control requests. Immediate mode: call draw() once per rendered picture between ImGui frames.
#pragma once

#include <optional>
#include <string>

#include "decoded_frame.h"
#include "network_client.h"
#include "render_settings.h"

namespace viewer {

struct ViewerRates {
  float render_fps = 0.0f;
  float arrival_to_pixels_ms = 0.0f;  // of the latest frame shown
  float frame_age_ms = -1.0f;         // send_time_us of the frame shown -> now (same-machine clocks)
};

class StatsPanel {
 public:
  explicit StatsPanel(NetworkClient& client) : client_(client) {}

  // `render` is the viewer's render mode, which the panel's switch changes.
  void draw(const DecodedFrame* frame, const NetworkStats& stats, const ViewerRates& rates, bool mouse_gaze,
            RenderMode& render);
  // Puts the latest reply (or its error) into the panel's message line.
  void showReply(const gsph::v1::ControlReply& reply);
  void togglePause(const DecodedFrame* frame);

 private:
  void drawControls(const DecodedFrame* frame, const std::optional<gsph::v1::ServerStatus>& status);
  NetworkClient& client_;
  std::string message_;
  int method_index_ = -1;
  float gaze_radius_ = 0.05f;
  bool gaze_radius_from_server_ = false;
  char scene_text_[128] = {};
};

const char* methodName(gsph::v1::Method method);

}  // namespace viewer
