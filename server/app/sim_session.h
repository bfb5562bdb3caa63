// The simulation as the server runs it: the scene, the Simulation, the adaptive controller and the
// camera its gaze projection uses, with the changes control requests make (load, reset, set method,
// set parameters). Owned and used by the simulation thread only.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "sph/adaptive/adaptive_controller.h"
#include "sph/adaptive/method.h"
#include "sph/camera.h"
#include "sph/scene.h"
#include "sph/simulation.h"

namespace app {

// Called just before each adaptive step, so the controller gets the freshest gaze the network thread
// has (a sample that arrives during the fluid stages still refines this step).
using BeforeAdaptiveStep = std::function<void(sph::AdaptiveController&)>;

class SimSession {
 public:
  // `overrides`: adaptive settings by key (sph/param_table.h) that replace the scene's own
  // "adaptive" values whenever a scene is loaded (the command line's --gaze-radius and friends).
  SimSession(std::string scene_dir, std::map<std::string, double> overrides, BeforeAdaptiveStep before);

  // The fluid preset every scene loads with from now on (sph::presetNames), or empty: each scene's
  // own. Takes effect at the next load; throws scene::SceneError for an unknown name.
  void usePreset(const std::string& preset);
  // Restarts the current scene with `preset` (same method and settings); later loads keep it.
  // Throws scene::SceneError for an unknown name, and then changes nothing. False when the scene
  // already ran it.
  bool setPreset(const std::string& preset);

  // Starts `scene` with `method` (none: the scene's default method) and the scene's adaptive settings
  // under the overrides. `scene` is a name in the scene folder, or with `allow_paths` (the command
  // line, never a remote peer) also a path to a scene file. Throws scene::SceneError or
  // std::exception when it cannot; the running simulation is then left as it was.
  void load(const std::string& scene, std::optional<sph::Method> method, bool allow_paths = false);
  // Restarts the current scene from its initial state, same method and settings.
  void reset();
  // Simulation parameters by key (sph/param_table.h) that replace the preset's and the scene
  // file's whenever a scene loads (the command line's --param). Each value must pass its
  // parameter's check; throws std::invalid_argument naming the first that does not.
  void useSimParameters(const std::map<std::string, double>& values);
  // Adds `values` to those and restarts the current scene with them (same method and settings).
  // Throws std::invalid_argument when one is out of range or they do not fit the scene's other
  // parameters (SimParams::validate), and then changes nothing.
  void setSimParameters(const std::map<std::string, double>& values);
  const std::map<std::string, double>& simParameters() const { return sim_parameters_; }

  // Between adaptive methods the controller switches in place and the particles stay; to or from
  // regular the particle set changes class wholesale, so the scene restarts. True when it restarted.
  bool setMethod(sph::Method method);
  // Validated by the caller (AdaptiveConfig::validate).
  void setConfig(const sph::AdaptiveConfig& config);
  // The foveated method's periphery gain in force (the real-time governor's); config() keeps the
  // configured one, which a restart brings back. Nothing for the other methods.
  void setPeripheryGain(double gain);
  // The foveated method's q and periphery gain in force; 0 for the other methods.
  double quality() const;
  double peripheryGain() const;
  // The camera the gaze projection uses; `from_client` false means the scene's default camera.
  void setCamera(const sph::ScreenCamera& camera, bool from_client);

  void step() { sim_->step(); }
  // What the eye gets from the particles as the last step left them (AdaptiveController::measureEye),
  // into controller()->lastStats(), for a method that sizes particles by acuity; once per step at
  // most. True when it measured (a step since the last measurement).
  bool measureEye();

  bool loaded() const { return sim_ != nullptr; }
  sph::Simulation& sim() { return *sim_; }
  const sph::Simulation& sim() const { return *sim_; }
  const sph::Scene& scene() const { return scene_; }
  const std::string& sceneDir() const { return scene_dir_; }
  // The preset the running simulation steps with (the override, or the scene's own).
  const std::string& preset() const { return scene_.params.preset; }
  sph::Method method() const { return method_; }
  const sph::AdaptiveConfig& config() const { return config_; }
  const sph::ScreenCamera& camera() const { return camera_; }
  bool cameraFromClient() const { return camera_from_client_; }
  // nullptr for the regular method.
  const sph::AdaptiveController* controller() const { return controller_; }

 private:
  void start(const sph::Scene& scene, sph::Method method, const sph::AdaptiveConfig& config);
  // The controller when the method sizes particles by acuity (sph::sizesByAcuity), else null.
  sph::AdaptiveController* foveatedController() const;

  std::string scene_dir_;
  std::string preset_override_;  // empty: each scene's own preset
  std::string scene_name_;       // what load() was given, so that setPreset can read the file again
  bool scene_allow_paths_ = false;
  std::map<std::string, double> overrides_;
  std::map<std::string, double> sim_parameters_;  // by the parameter's key, never an alias
  sph::AdaptiveConfig config_;
  BeforeAdaptiveStep before_;
  sph::Scene scene_;
  sph::Method method_{};             // load() sets it
  std::int64_t measured_step_ = -1;  // the step measureEye last measured
  sph::ScreenCamera camera_;
  bool camera_from_client_ = false;
  std::unique_ptr<sph::Simulation> sim_;
  sph::AdaptiveController* controller_ = nullptr;  // owned by sim_ through the adaptive step
};

}  // namespace app
