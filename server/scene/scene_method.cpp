#include "scene/scene_method.h"

#include "scene/scene_loader.h"
#include "sph/solvers/fluid_solver_factory.h"

namespace scene {

bool solverHasLevelsOf(const sph::Scene& scene, sph::Method method) {
  const int levels_needed = sph::levelIndex(sph::coarsestLevel(method, scene.params.levels)) + 1;
  return levels_needed <= sph::kThesisLevels || levels_needed <= sph::makeFluidSolver(scene)->sizeLevels();
}

sph::Method ownMethod(const sph::Scene& scene) {
  sph::Method method;
  if (!sph::methodByName(scene.method, method)) {
    throw SceneError(scene.source + ": unknown method '" + scene.method + "'");
  }
  return solverHasLevelsOf(scene, method) ? method : sph::Method::Gaze;
}

}  // namespace scene
