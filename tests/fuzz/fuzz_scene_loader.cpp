// The scene loader (server/scene/scene_loader.h) on JSON text: scene files and load_scene names come
// from users, so any text must give a complete scene or a SceneError, and nothing else.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_check.h"
#include "scene/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const sph::Scene scene = scene::parseScene(text, "fuzz.json");
    FUZZ_CHECK(scene.boundary.box.contains(scene.water.min) && scene.boundary.box.contains(scene.water.max));
    FUZZ_CHECK((scene.boundary.box.max.array() > scene.boundary.box.min.array()).all());
    FUZZ_CHECK(scene.large_particles > 0);
  } catch (const scene::SceneError&) {
    // the documented refusal
  }
  return 0;
}
