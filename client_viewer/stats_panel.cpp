#include "stats_panel.h"

#include "foveation_readout.h"
#include "level_colours.h"
#include "study_plan.h"

#include <imgui.h>

#include <cstdio>
#include <iterator>
#include <string>

namespace viewer {

namespace {

constexpr gsph::v1::Method kMethods[] = {gsph::v1::METHOD_REGULAR, gsph::v1::METHOD_SURFACE, gsph::v1::METHOD_GAZE,
                                         gsph::v1::METHOD_HYBRID, gsph::v1::METHOD_FOVEATED};
constexpr int kMethodCount = static_cast<int>(std::size(kMethods));
constexpr float kMinGazeRadius = 0.005f;
constexpr float kMaxGazeRadius = 0.5f;

// "particles N: L0 a, L1 b, ...", every level of the frame, finest first.
void showParticleCounts(const DecodedFrame& frame) {
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string here.
  std::string line = "particles ";
  line += std::to_string(frame.particleCount());
  line += ": ";
  line += levelCountsText(frame);
  ImGui::TextUnformatted(line.c_str());
}

// One swatch per level in its colour (particles mode, the foveated rings), finest first.
void showLevelLegend(const DecodedFrame& frame) {
  ImGui::TextUnformatted("levels ");
  const std::size_t count = frame.colourLevelCount();
  for (std::size_t level = 0; level < count; ++level) {
    const LevelRgb c = levelColour(level, count);
    ImGui::SameLine();
    ImGui::ColorButton(("##level" + std::to_string(level)).c_str(), ImVec4(c.r, c.g, c.b, 1.0f),
                       ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoDragDrop, ImVec2(14, 14));
    ImGui::SameLine();
    ImGui::Text("L%zu", level);
  }
}

}  // namespace

const char* methodName(gsph::v1::Method method) {
  const char* name = studyMethodName(method);
  return name != nullptr ? name : "?";
}

void StatsPanel::showReply(const gsph::v1::ControlReply& reply) {
  char line[320];
  if (reply.ok()) {
    std::snprintf(line, sizeof(line), "request %llu ok", static_cast<unsigned long long>(reply.request_id()));
  } else {
    std::snprintf(line, sizeof(line), "request %llu failed: %s", static_cast<unsigned long long>(reply.request_id()),
                  reply.error().c_str());
  }
  message_ = line;
}

void StatsPanel::togglePause(const DecodedFrame* frame) {
  gsph::v1::Control request;
  if (frame != nullptr && frame->paused) {
    request.mutable_resume();
  } else {
    request.mutable_pause();
  }
  client_.sendControl(std::move(request));
}

void StatsPanel::draw(const DecodedFrame* frame, const NetworkStats& stats, const ViewerRates& rates, bool mouse_gaze,
                      RenderMode& render) {
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.75f);
  if (!ImGui::Begin("sph_viewer", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::End();
    return;
  }
  ImGui::Text("viewer  %.1f fps, arrival->pixels %.1f ms", rates.render_fps, rates.arrival_to_pixels_ms);
  int mode = static_cast<int>(render);
  ImGui::Text("render ");
  ImGui::SameLine();
  ImGui::RadioButton("fluid", &mode, static_cast<int>(RenderMode::kFluid));
  ImGui::SameLine();
  ImGui::RadioButton("particles", &mode, static_cast<int>(RenderMode::kParticles));
  render = static_cast<RenderMode>(mode);
  ImGui::Text(
      "frames  %llu received, %llu skipped, %llu rejected", static_cast<unsigned long long>(stats.frames_received),
      static_cast<unsigned long long>(stats.frames_skipped), static_cast<unsigned long long>(stats.frames_rejected));
  if (frame != nullptr) {
    ImGui::Separator();
    ImGui::Text("scene   %s   method %s%s", frame->scene.c_str(), methodName(frame->method),
                frame->paused ? "   PAUSED" : "");
    ImGui::Text("server  %.1f steps/s, step %lld, t = %.2f s", frame->steps_per_second,
                static_cast<long long>(frame->step), frame->sim_time);
    showParticleCounts(*frame);
    const auto& t = frame->timings;
    ImGui::Text("ms  neighbours %.2f  density+pressure %.2f", t.neighbor_ms(), t.density_pressure_ms());
    ImGui::Text("    accel+integrate+collide %.2f  adaptive %.2f  total %.2f", t.accel_integrate_collide_ms(),
                t.adaptive_ms(), t.total_ms());
    if (render == RenderMode::kParticles || frame->method == gsph::v1::METHOD_FOVEATED) showLevelLegend(*frame);
    for (const std::string& line : foveationLines(*frame)) ImGui::TextUnformatted(line.c_str());
    if (frame->gaze.age_ms >= 0.0f) ImGui::Text("        sample age %.0f ms", frame->gaze.age_ms);
    if (frame->method == gsph::v1::METHOD_GAZE || frame->method == gsph::v1::METHOD_HYBRID) {
      ImGui::Text("        circle radius %.3f W", frame->gaze.radius);
    }
    ImGui::Text("frame   seq %llu, age %.1f ms, %s, %zu KB", static_cast<unsigned long long>(frame->sequence),
                rates.frame_age_ms,
                frame->encoding == gsph::v1::POSITION_ENCODING_QUANTIZED16 ? "quantized16" : "float32",
                frame->wire_bytes / 1024);
  }
  if (mouse_gaze)
    ImGui::Text("gaze from this viewer: %llu samples sent", static_cast<unsigned long long>(stats.gaze_sent));
  if (!stats.last_error.empty())
    ImGui::TextColored(ImVec4(1, 0.5f, 0.3f, 1), "last error: %s", stats.last_error.c_str());
  ImGui::Separator();
  drawControls(frame, client_.latestStatus());
  ImGui::End();
}

void StatsPanel::drawControls(const DecodedFrame* frame, const std::optional<gsph::v1::ServerStatus>& status) {
  if (ImGui::Button(frame != nullptr && frame->paused ? "Resume" : "Pause")) togglePause(frame);
  ImGui::SameLine();
  if (ImGui::Button("Reset")) {
    gsph::v1::Control request;
    request.mutable_reset();
    client_.sendControl(std::move(request));
  }

  // Scene: the server's list when a status reply has arrived, else a free text field.
  if (status && status->scenes_size() > 0) {
    const std::string current = frame != nullptr ? frame->scene : status->scene();
    if (ImGui::BeginCombo("scene", current.c_str())) {
      for (const auto& name : status->scenes()) {
        if (ImGui::Selectable(name.c_str(), name == current)) {
          gsph::v1::Control request;
          request.mutable_load_scene()->set_scene(name);
          client_.sendControl(std::move(request));
        }
      }
      ImGui::EndCombo();
    }
  } else {
    ImGui::InputText("scene", scene_text_, sizeof(scene_text_));
    ImGui::SameLine();
    if (ImGui::Button("Load") && scene_text_[0] != '\0') {
      gsph::v1::Control request;
      request.mutable_load_scene()->set_scene(scene_text_);
      client_.sendControl(std::move(request));
    }
  }

  const char* labels[kMethodCount];
  for (int i = 0; i < kMethodCount; ++i) {
    labels[i] = methodName(kMethods[i]);
    if (frame != nullptr && kMethods[i] == frame->method) method_index_ = i;
  }
  int chosen = method_index_;
  if (ImGui::Combo("method", &chosen, labels, kMethodCount) && chosen != method_index_ && chosen >= 0) {
    gsph::v1::Control request;
    request.mutable_set_method()->set_method(kMethods[chosen]);
    client_.sendControl(std::move(request));
  }

  // Gaze radius as a fraction of the viewport width; starts from the server's value.
  if (!gaze_radius_from_server_ && status) {
    const auto it = status->parameters().find("gaze_radius");
    if (it != status->parameters().end()) {
      gaze_radius_ = static_cast<float>(it->second);
      gaze_radius_from_server_ = true;
    }
  }
  ImGui::SliderFloat("gaze radius (x W)", &gaze_radius_, kMinGazeRadius, kMaxGazeRadius, "%.3f");
  if (ImGui::IsItemDeactivatedAfterEdit()) {
    gsph::v1::Control request;
    (*request.mutable_set_parameters()->mutable_values())["gaze_radius"] = gaze_radius_;
    client_.sendControl(std::move(request));
  }
  if (!message_.empty()) ImGui::TextWrapped("%s", message_.c_str());
}

}  // namespace viewer
