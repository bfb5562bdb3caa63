// Reads scene files (JSON) into sph::Scene. Every error names the file and the key, and nothing is
// half-loaded: the function returns a complete scene or throws SceneError.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "sph/scene.h"

namespace scene {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The folder holding the shipped scenes: $SPH_SCENE_DIR when set, else the source tree's scenes/.
std::string defaultSceneDir();

// Names of the scenes in `dir` (file stems of *.json), sorted.
std::vector<std::string> listScenes(const std::string& dir);

// `name_or_path` is a path to a .json file, or the name of a scene in `dir`. A non-empty `preset`
// (sph::presetNames) replaces the scene's own "preset"; the scene's "params" still apply on top.
sph::Scene loadScene(const std::string& name_or_path, const std::string& dir = defaultSceneDir(),
                     const std::string& preset = "");

// Parses scene JSON text; `source` names it in messages; `preset` as for loadScene.
sph::Scene parseScene(const std::string& json_text, const std::string& source, const std::string& preset = "");

// The preset names, comma separated, for messages.
std::string knownPresetList();

}  // namespace scene
