#include "app/control_executor.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <exception>
#include <map>
#include <string>

#include "net/frame_encoder.h"
#include "net/peer_text.h"
#include "scene/scene_loader.h"
#include "sph/param_table.h"

namespace app {
namespace {

using gsph::v1::ControlReply;
using gsph::v1::ErrorCode;

bool asBool(double v, bool& out) {
  if (v != 0.0 && v != 1.0) return false;
  out = v == 1.0;
  return true;
}

// Checks every value on copies and applies them all only when all pass.
std::string applyParameters(const gsph::v1::SetParametersRequest& request, ControlTarget& target,
                            ControlEffects& effects) {
  if (request.values().empty()) return "no parameters given";
  sph::AdaptiveConfig config = target.session.config();
  RunSettings settings = target.settings;
  std::map<std::string, double> simulation;
  for (const auto& [name, value] : request.values()) {
    if (!std::isfinite(value)) return "parameter '" + net::echoText(name) + "' is not finite";
    if (const sph::ParamSpec* spec = sph::findParameter(name); spec != nullptr) {
      if (const std::string why = spec->check(value); !why.empty()) {
        return std::string("parameter '") + spec->key + "' " + (spec->isFlag() ? "must be 0 or 1" : why);
      }
      if (spec->isAdaptive()) {
        spec->set(config, value);
      } else {
        simulation[spec->key] = value;
      }
    } else if (name == "publish_hz") {
      if (std::string e = publishHzError(value); !e.empty()) return e;
      settings.publish_hz = value;
    } else if (name == "quantized") {
      if (!asBool(value, settings.quantized)) return name + " must be 0 or 1";
    } else if (name == "free_run") {
      if (!asBool(value, settings.free_run)) return name + " must be 0 or 1";
    } else {
      return "unknown parameter '" + net::echoText(name) +
             "': neither a setting (sph_bench --parameter-table lists them) nor publish_hz, quantized or free_run";
    }
  }
  try {
    config.validate();
    // Simulation parameters restart the scene with them: last of the checks, first of the changes.
    if (!simulation.empty()) target.session.setSimParameters(simulation);
  } catch (const std::exception& e) {
    return e.what();
  }
  if (!simulation.empty()) spdlog::info("simulation parameters set: the scene restarted");
  effects.restart_clock = !simulation.empty() || settings.free_run != target.settings.free_run;
  target.session.setConfig(config);
  target.settings = settings;
  return {};
}

void fail(ControlReply& reply, ErrorCode code, const std::string& error) {
  reply.set_ok(false);
  reply.set_error_code(code);
  // Whatever the message quotes (an exception's text included), the reply and the log line that
  // repeats it stay short and printable.
  reply.set_error(net::echoText(error, net::kMaxErrorBytes));
}

}  // namespace

std::string publishHzError(double hz) {
  if (std::isfinite(hz) && hz >= kMinPublishHz && hz <= kMaxPublishHz) return {};
  return fmt::format("publish_hz must be between {} and {} frames per second", kMinPublishHz, kMaxPublishHz);
}

void fillStatus(ControlTarget& target, gsph::v1::ServerStatus& status) {
  const SimSession& s = target.session;
  status.set_scene(s.scene().name);
  status.set_method(net::toProtoMethod(s.method()));
  status.set_preset(s.preset());
  status.set_paused(target.settings.paused);
  const sph::ParticleSet& p = s.sim().particles();
  status.set_step(s.sim().stepCount());
  status.set_sim_time(s.sim().time());
  status.set_particle_count(static_cast<std::uint32_t>(p.size()));
  net::setLevelCounts(s.sim(), status);
  status.clear_scenes();
  try {
    for (const std::string& name : scene::listScenes(s.sceneDir())) status.add_scenes(name);
  } catch (const std::exception& e) {
    spdlog::debug("cannot list scenes: {}", e.what());
  }
  auto& params = *status.mutable_parameters();
  params["publish_hz"] = target.settings.publish_hz;
  params["quantized"] = target.settings.quantized ? 1.0 : 0.0;
  params["free_run"] = target.settings.free_run ? 1.0 : 0.0;
  for (const sph::ParamSpec& spec : sph::parameterTable()) {
    params[spec.key] = spec.isAdaptive() ? spec.get(s.config()) : spec.get(s.scene().params);
  }
  if (target.fill_counters) target.fill_counters(status);
}

ControlReply executeControl(const gsph::v1::Control& request, ControlTarget& target, ControlEffects& effects) {
  ControlReply reply;
  reply.set_protocol_version(gsph::v1::PROTOCOL_VERSION_CURRENT);
  reply.set_request_id(request.request_id());
  reply.set_ok(true);
  reply.set_error_code(gsph::v1::ERROR_CODE_NONE);
  SimSession& session = target.session;
  try {
    switch (request.command_case()) {
      case gsph::v1::Control::kStatus:
        break;
      case gsph::v1::Control::kPause:
        target.settings.paused = true;
        break;
      case gsph::v1::Control::kResume:
        effects.restart_clock = target.settings.paused;
        target.settings.paused = false;
        break;
      case gsph::v1::Control::kReset:
        session.reset();
        effects.restart_clock = true;
        break;
      case gsph::v1::Control::kLoadScene:
        try {
          session.load(request.load_scene().scene(), session.method());  // names only
          effects.restart_clock = true;
        } catch (const scene::SceneError& e) {
          fail(reply, gsph::v1::ERROR_CODE_UNKNOWN_SCENE, e.what());
        }
        break;
      case gsph::v1::Control::kSetMethod: {
        sph::Method method;
        if (!net::fromProtoMethod(request.set_method().method(), method)) {
          fail(reply, gsph::v1::ERROR_CODE_UNKNOWN_METHOD,
               "unknown method value " + std::to_string(request.set_method().method()));
          break;
        }
        // To or from regular or foveated the scene restarts (the levels change wholesale).
        const sph::Method before = session.method();
        try {
          if (session.setMethod(method)) {
            effects.restart_clock = true;
            spdlog::info("method {} -> {}: the scene restarted", sph::methodName(before), sph::methodName(method));
          } else {
            spdlog::info("method {} -> {}", sph::methodName(before), sph::methodName(method));
          }
        } catch (const std::invalid_argument& e) {
          // A method the preset's solver cannot run (foveated on the thesis's): nothing changed.
          fail(reply, gsph::v1::ERROR_CODE_BAD_PARAMETER, e.what());
        }
        break;
      }
      case gsph::v1::Control::kSetPreset: {
        const std::string& wanted = request.set_preset().preset();
        const std::string before = session.preset();
        try {
          if (wanted.empty())
            throw scene::SceneError("set_preset needs a preset (known: " + scene::knownPresetList() + ")");
          if (session.setPreset(wanted)) {
            effects.restart_clock = true;
            spdlog::info("preset {} -> {}: the scene restarted", before, wanted);
          }
        } catch (const scene::SceneError& e) {
          fail(reply, gsph::v1::ERROR_CODE_UNKNOWN_PRESET, e.what());
        } catch (const std::invalid_argument& e) {
          // A preset whose solver cannot run the method (the thesis's under foveated): nothing changed.
          fail(reply, gsph::v1::ERROR_CODE_BAD_PARAMETER, e.what());
        }
        break;
      }
      case gsph::v1::Control::kSetParameters: {
        const std::string error = applyParameters(request.set_parameters(), target, effects);
        if (!error.empty()) fail(reply, gsph::v1::ERROR_CODE_BAD_PARAMETER, error);
        break;
      }
      case gsph::v1::Control::COMMAND_NOT_SET:
        fail(reply, gsph::v1::ERROR_CODE_BAD_REQUEST, "no command");
        break;
    }
  } catch (const std::exception& e) {
    fail(reply, gsph::v1::ERROR_CODE_INTERNAL, e.what());
  }
  fillStatus(target, *reply.mutable_status());
  return reply;
}

}  // namespace app
