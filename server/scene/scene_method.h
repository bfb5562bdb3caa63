// Which method a scene runs: its own, as far as the solver its preset picks can run it.
#pragma once

#include "sph/adaptive/method.h"
#include "sph/scene.h"

namespace scene {

// Whether the scene's solver (after its preset) has the size levels `method` uses. Every solver
// has the thesis's two classes, so only a method with more builds the solver to ask it.
bool solverHasLevelsOf(const sph::Scene& scene, sph::Method method);

// The method a scene runs when the caller names none: its own ("method"), or the thesis's gaze
// where its solver lacks that method's levels (foveated on the thesis's). Throws SceneError for
// an unknown name.
sph::Method ownMethod(const sph::Scene& scene);

}  // namespace scene
