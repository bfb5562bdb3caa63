#include "app/sim_session.h"

#include <algorithm>
#include <stdexcept>

#include "net/peer_text.h"
#include "scene/scene_loader.h"
#include "scene/scene_method.h"
#include "sph/param_table.h"

namespace app {
namespace {

// Installs the controller as the simulation's adaptive step and calls `before` ahead of it.
class FedAdaptiveStep : public sph::AdaptiveStep {
 public:
  FedAdaptiveStep(std::unique_ptr<sph::AdaptiveController> controller, BeforeAdaptiveStep before)
      : controller_(std::move(controller)), before_(std::move(before)) {}
  void apply(sph::Simulation& sim) override {
    if (before_) before_(*controller_);
    controller_->apply(sim);
  }
  sph::Level coarsest() const override { return controller_->coarsest(); }

 private:
  std::unique_ptr<sph::AdaptiveController> controller_;
  BeforeAdaptiveStep before_;
};

// `values` by key into `into` and onto `params`; throws std::invalid_argument for an unknown key or
// a value out of its parameter's range.
void addSimParameters(const std::map<std::string, double>& values, std::map<std::string, double>& into,
                      sph::SimParams& params) {
  for (const auto& [name, value] : values) {
    const sph::ParamSpec* spec = sph::findParameter(name);
    if (spec == nullptr || spec->isAdaptive()) {
      throw std::invalid_argument("unknown simulation parameter '" + net::echoText(name) + "'");
    }
    if (const std::string why = spec->check(value); !why.empty()) {
      throw std::invalid_argument(std::string("parameter '") + spec->key + "' " + why);
    }
    into[spec->key] = value;
    spec->set(params, value);
  }
}

}  // namespace

SimSession::SimSession(std::string scene_dir, std::map<std::string, double> overrides, BeforeAdaptiveStep before)
    : scene_dir_(std::move(scene_dir)), overrides_(std::move(overrides)), before_(std::move(before)) {}

void SimSession::load(const std::string& scene_name, std::optional<sph::Method> method, bool allow_paths) {
  // Remote peers get names from the scene folder only: they must not make the server read any path.
  const std::vector<std::string> names = scene::listScenes(scene_dir_);
  if (!allow_paths && std::find(names.begin(), names.end(), scene_name) == names.end()) {
    throw scene::SceneError("no scene '" + net::echoText(scene_name) + "' in " + scene_dir_);
  }
  sph::Scene scene = scene::loadScene(scene_name, scene_dir_, preset_override_);
  std::map<std::string, double> unused;
  addSimParameters(sim_parameters_, unused, scene.params);
  // A method the caller names is refused where the solver lacks its levels; the scene's own gives
  // way to gaze there.
  const sph::Method chosen = method ? *method : scene::ownMethod(scene);
  start(scene, chosen, sph::withAdaptiveSettings(scene.adaptive, overrides_));
  scene_name_ = scene_name;
  scene_allow_paths_ = allow_paths;
}

void SimSession::usePreset(const std::string& preset) {
  sph::SimParams unused;
  if (!preset.empty() && !sph::presetByName(preset, unused)) {
    throw scene::SceneError("unknown preset '" + net::echoText(preset) + "' (known: " + scene::knownPresetList() + ")");
  }
  preset_override_ = preset;
}

bool SimSession::setPreset(const std::string& preset) {
  if (preset == this->preset()) return false;
  const std::string before = preset_override_;
  usePreset(preset);
  try {
    // The file again: its own "params" apply on top of the new preset, as at a first load.
    load(scene_name_, method_, scene_allow_paths_);
  } catch (...) {
    preset_override_ = before;
    throw;
  }
  return true;
}

void SimSession::useSimParameters(const std::map<std::string, double>& values) {
  std::map<std::string, double> merged = sim_parameters_;
  sph::SimParams unused;
  addSimParameters(values, merged, unused);
  sim_parameters_ = std::move(merged);
}

void SimSession::setSimParameters(const std::map<std::string, double>& values) {
  std::map<std::string, double> merged = sim_parameters_;
  sph::Scene scene = scene_;
  addSimParameters(values, merged, scene.params);
  start(scene, method_, config_);  // validates the parameters together; a throw changes nothing
  sim_parameters_ = std::move(merged);
}

void SimSession::reset() { start(scene_, method_, config_); }

bool SimSession::setMethod(sph::Method method) {
  if (method == method_) return false;
  // Between methods of the same levels the controller switches in place; a method of other
  // levels needs another neighbour grid (and foveated's water starts coarsest): a restart.
  if (controller_ != nullptr && sph::adapts(method) &&
      sph::coarsestLevel(method, scene_.params.levels) == sph::coarsestLevel(method_, scene_.params.levels)) {
    controller_->setMethod(method);
    method_ = method;
    return false;
  }
  start(scene_, method, config_);
  return true;
}

void SimSession::setConfig(const sph::AdaptiveConfig& config) {
  config_ = config;
  if (controller_ != nullptr) controller_->setConfig(config_);
}

sph::AdaptiveController* SimSession::foveatedController() const {
  return sph::sizesByAcuity(method_) ? controller_ : nullptr;
}

void SimSession::setPeripheryGain(double gain) {
  sph::AdaptiveController* foveated = foveatedController();
  if (foveated == nullptr) return;
  sph::AdaptiveConfig in_force = foveated->config();
  in_force.foveated_periphery_gain = gain;
  foveated->setConfig(in_force);
}

double SimSession::quality() const {
  const sph::AdaptiveController* foveated = foveatedController();
  return foveated != nullptr ? foveated->config().foveated_quality : 0.0;
}

double SimSession::peripheryGain() const {
  const sph::AdaptiveController* foveated = foveatedController();
  return foveated != nullptr ? foveated->config().foveated_periphery_gain : 0.0;
}

void SimSession::setCamera(const sph::ScreenCamera& camera, bool from_client) {
  camera_ = camera;
  camera_from_client_ = from_client;
  if (controller_ != nullptr) controller_->setCamera(camera_);
}

void SimSession::start(const sph::Scene& scene, sph::Method method, const sph::AdaptiveConfig& config) {
  // Room for every particle to split to L0 (the thesis's 20,000 for 10,000 L1).
  const std::size_t capacity = sph::refinedCapacity(scene);
  // Build everything first, then swap: a throw leaves the running simulation untouched.
  auto sim = std::make_unique<sph::Simulation>(scene, sph::startLevel(method, scene.params.levels), capacity);
  const sph::ScreenCamera camera = camera_from_client_ ? camera_ : sph::cameraFromSpec(scene.camera);
  sph::AdaptiveController* controller = nullptr;
  if (auto owned = sph::makeAdaptiveController(method, scene.params.levels, config, camera)) {
    controller = owned.get();
    controller->setMeasureEachStep(false);  // measureEye: once per published frame
    sim->setAdaptiveStep(std::make_unique<FedAdaptiveStep>(std::move(owned), before_));
  }
  scene_ = scene;
  method_ = method;
  config_ = config;
  camera_ = camera;
  sim_ = std::move(sim);
  controller_ = controller;
  measured_step_ = -1;
}

bool SimSession::measureEye() {
  if (controller_ == nullptr || !sph::sizesByAcuity(method_)) return false;
  const auto step = static_cast<std::int64_t>(sim_->stepCount());
  if (step == measured_step_) return false;
  measured_step_ = step;
  controller_->measureEye(*sim_);
  return true;
}

}  // namespace app
