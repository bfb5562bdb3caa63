// Scene files: the five shipped scenes load; bad files fail with the file and key named.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "scene/scene_loader.h"
#include "sph/fill_water.h"
#include "sph/params.h"
#include "sph/particles.h"
#include "sph/solvers/fluid_solver_factory.h"
#include "support/test_setting.h"

namespace {

const char* kMinimal = R"({"box": {"min": [0,0,0], "max": [1,1,1]},
                           "water": {"min": [0,0,0], "max": [1,0.5,1]}, "large_particles": 100})";

std::string errorOf(const std::string& text) {
  try {
    scene::parseScene(text, "test.json");
  } catch (const scene::SceneError& e) {
    return e.what();
  }
  return "";
}

std::string withKey(const std::string& extra) {
  std::string s = kMinimal;
  s.insert(1, extra + ",");
  return s;
}

}  // namespace

TEST(SceneLoader, ShippedScenesLoadAndFill) {
  const auto names = scene::listScenes(scene::defaultSceneDir());
  for (const char* expected : {"basin", "dambreak", "dambreak_obstacles", "large_box", "small_box", "wave"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  }
  for (const auto& name : names) {
    const sph::Scene s = scene::loadScene(name);
    // The thesis's scenes have its 10,000 L1 particles; the basin ten times the dam break's water.
    const int large = name == "basin" ? 100000 : 10000;
    EXPECT_EQ(s.large_particles, large) << name;
    sph::ParticleSet small_set(sph::refinedCapacity(s)), large_set(sph::refinedCapacity(s));
    const auto solver = sph::makeFluidSolver(s);
    sph::fillWater(s, sph::Level{0}, *solver, small_set);
    sph::fillWater(s, sph::Level{1}, *solver, large_set);
    EXPECT_EQ(small_set.size(), 2u * static_cast<unsigned>(large)) << name;
    EXPECT_EQ(large_set.size(), static_cast<unsigned>(large)) << name;
    // The same water mass either way.
    EXPECT_NEAR(small_set.totalMass(), large_set.totalMass(), 1e-3) << name;
  }
}

// The particles left over for the top layer spread over the whole footprint: a partial layer
// filled row by row covered one side of it, a step in the surface that set the water sloshing.
TEST(SceneLoader, FillSpreadsTheTopLayerOverTheFootprint) {
  for (const char* preset : {"thesis", "pbf"}) {
    sph::Scene s = scene::loadScene("dambreak");
    ASSERT_TRUE(sph::presetByName(preset, s.params));
    for (const sph::Level c : {sph::Level{0}, sph::Level{1}}) {
      sph::ParticleSet p;
      sph::fillWater(s, c, *sph::makeFluidSolver(s), p);
      float top = 0.0f;
      for (const sph::Vec3& x : p.position) top = std::max(top, x.y());
      const auto centre = (s.water.min + s.water.max).cast<float>() / 2.0f;
      int quadrant[4] = {};
      int in_top = 0;
      for (const sph::Vec3& x : p.position) {
        if (x.y() < top - 1e-4f) continue;
        ++in_top;
        ++quadrant[(x.x() < centre.x() ? 0 : 1) + (x.z() < centre.z() ? 0 : 2)];
      }
      ASSERT_GT(in_top, 40) << preset;
      for (const int q : quadrant) EXPECT_NEAR(q, in_top / 4.0, 0.05 * in_top) << preset << " " << in_top;
    }
  }
}

TEST(SceneLoader, MinimalSceneGetsThesisDefaults) {
  const sph::Scene s = scene::parseScene(kMinimal, "test.json");
  EXPECT_DOUBLE_EQ(s.params.gas_stiffness, 3.0);
  EXPECT_DOUBLE_EQ(s.params.time_step, 0.01);
  EXPECT_EQ(s.frames, 900);
}

TEST(SceneLoader, ParamsOverrideThePreset) {
  const sph::Scene s = scene::parseScene(withKey(R"("params": {"gas_stiffness": 30, "time_step": 0.003})"), "t");
  EXPECT_DOUBLE_EQ(s.params.gas_stiffness, 30.0);
  EXPECT_DOUBLE_EQ(s.params.time_step, 0.003);
}

TEST(SceneLoader, PbfIterationBoundsAreReadAndChecked) {
  const sph::Scene s = scene::parseScene(
      withKey(R"("preset": "pbf", "params": {"pbf_density_tolerance": 0, "pbf_max_iterations": 8})"), "t");
  EXPECT_DOUBLE_EQ(s.params.pbf_density_tolerance, 0.0);
  EXPECT_EQ(s.params.pbf_max_iterations, 8);
  EXPECT_GT(scene::parseScene(withKey(R"("preset": "pbf")"), "t").params.pbf_density_tolerance, 0.0);
  EXPECT_NE(errorOf(withKey(R"("params": {"pbf_density_tolerance": -0.01})")).find("params.pbf_density_tolerance"),
            std::string::npos);
  EXPECT_NE(errorOf(withKey(R"("params": {"pbf_max_iterations": 0})")).find("params.pbf_max_iterations"),
            std::string::npos);
  EXPECT_NE(errorOf(withKey(R"("params": {"pbf_max_iterations": 500})")).find("pbf_max_iterations"), std::string::npos);
}

TEST(SceneLoader, PbfRelaxationFactorIsReadAndChecked) {
  EXPECT_DOUBLE_EQ(scene::parseScene(withKey(R"("preset": "pbf", "params": {"pbf_omega": 0.5})"), "t").params.pbf_omega,
                   0.5);
  EXPECT_NE(errorOf(withKey(R"("params": {"pbf_omega": 0})")).find("params.pbf_omega"), std::string::npos);
  EXPECT_NE(errorOf(withKey(R"("params": {"pbf_omega": 1.5})")).find("params.pbf_omega': must be a number in (0, 1]"),
            std::string::npos);
}

TEST(SceneLoader, DfsphSolveChoiceIsReadAndChecked) {
  EXPECT_TRUE(scene::parseScene(withKey(R"("preset": "dfsph")"), "t").params.dfsph_conjugate_gradients);
  EXPECT_FALSE(scene::parseScene(withKey(R"("preset": "dfsph", "params": {"dfsph_conjugate_gradients": false})"), "t")
                   .params.dfsph_conjugate_gradients);
  EXPECT_NE(
      errorOf(withKey(R"("params": {"dfsph_conjugate_gradients": "no"})")).find("params.dfsph_conjugate_gradients"),
      std::string::npos);
}

// A renamed key keeps loading under its old name (sph/param_table.h, ParamSpec::alias).
TEST(SceneLoader, RenamedParameterKeysStillLoadUnderTheirOldNames) {
  const sph::Scene s =
      scene::parseScene(withKey(R"("preset": "dfsph", "params": {"cfl": 0.3, "max_iterations": 50})"), "t");
  EXPECT_DOUBLE_EQ(s.params.dfsph_cfl, 0.3);
  EXPECT_EQ(s.params.dfsph_max_iterations, 50);
  EXPECT_NE(errorOf(withKey(R"("params": {"max_iterations": 2.5})")).find("params.max_iterations"), std::string::npos);
}

TEST(SceneLoader, CallersPresetReplacesTheScenesAndParamsStillApply) {
  const std::string text = withKey(R"("preset": "thesis", "params": {"xsph_viscosity": 0.05})");
  const sph::Scene s = scene::parseScene(text, "t", "dfsph");
  EXPECT_EQ(s.params.preset, "dfsph");
  EXPECT_EQ(s.params.solver, "dfsph");
  EXPECT_DOUBLE_EQ(s.params.xsph_viscosity, 0.05);
  EXPECT_EQ(scene::parseScene(text, "t").params.preset, "thesis");
}

TEST(SceneLoader, UnknownCallerPresetListsTheKnownOnes) {
  try {
    scene::parseScene(kMinimal, "t", "water");
    FAIL() << "an unknown preset loaded";
  } catch (const scene::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown preset 'water' (known: thesis, pbf, dfsph)"), std::string::npos)
        << e.what();
  }
}

TEST(SceneLoader, UnknownKeyIsNamed) {
  const std::string e = errorOf(withKey(R"("bogus": 1)"));
  EXPECT_NE(e.find("test.json"), std::string::npos) << e;
  EXPECT_NE(e.find("'bogus'"), std::string::npos) << e;
}

TEST(SceneLoader, UnknownParameterIsNamed) {
  const std::string e = errorOf(withKey(R"("params": {"stiffness": 3})"));
  EXPECT_NE(e.find("params.stiffness"), std::string::npos) << e;
}

TEST(SceneLoader, NegativeAndNonFiniteSizesAreRejected) {
  EXPECT_NE(errorOf(withKey(R"("spheres": [{"centre": [0.5,0.5,0.5], "radius": -1}])")).find("spheres[0].radius"),
            std::string::npos);
  // JSON has no NaN literal; a string where a number belongs is the nearest a file can get.
  EXPECT_NE(errorOf(withKey(R"("cylinders": [{"x": "nan", "z": 0, "radius": 0.1}])")).find("cylinders[0].x"),
            std::string::npos);
  EXPECT_NE(errorOf(withKey(R"("params": {"rest_density": 0})")).find("params.rest_density"), std::string::npos);
  EXPECT_NE(
      errorOf(R"({"box": {"min": [0,0,0], "max": [1,-1,1]}, "water": {"min": [0,0,0], "max": [1,1,1]}})").find("'box'"),
      std::string::npos);
}

// A split halves a particle's mass and a merge adds two: classes of other masses would leave split
// children with a mass that is not their class's.
TEST(SceneLoader, ClassMassesOtherThanOneToTwoAreRejected) {
  const sph::Scene s = scene::parseScene(withKey(R"("params": {"mass_small": 0.005, "mass_large": 0.01})"), "t");
  EXPECT_DOUBLE_EQ(s.params.mass_small, 0.005);
  const std::string e = errorOf(withKey(R"("params": {"mass_small": 0.01, "mass_large": 0.03})"));
  EXPECT_NE(e.find("'mass_large' must be twice 'mass_small'"), std::string::npos) << e;
  // Twice the mass over half the kernel particles: the same support for L0 and L1.
  const std::string same =
      errorOf(withKey(R"("params": {"kernel_particles_small": 40, "kernel_particles_large": 20})"));
  EXPECT_NE(same.find("give two levels one support"), std::string::npos) << same;
}

TEST(SceneLoader, WaterOutsideTheBoxIsRejected) {
  const std::string e =
      errorOf(R"({"box": {"min": [0,0,0], "max": [1,1,1]}, "water": {"min": [0,0,0], "max": [2,1,1]}})");
  EXPECT_NE(e.find("'water'"), std::string::npos) << e;
}

TEST(SceneLoader, MissingKeyAndBadJsonAreReported) {
  EXPECT_NE(errorOf(R"({"box": {"min": [0,0,0], "max": [1,1,1]}})").find("'water'"), std::string::npos);
  EXPECT_NE(errorOf("{not json").find("not valid JSON"), std::string::npos);
}

TEST(SceneLoader, NumberBeyondDoubleRangeIsASceneError) {
  // Found by tests/fuzz/fuzz_scene_loader (its input, verbatim): nlohmann reports a number too large
  // for a double as out_of_range, not parse_error, and it escaped parseScene as a non-SceneError.
  const std::string fuzz_input("[\n 7777e7737!76\xef\xef\xaf\n");
  EXPECT_NE(errorOf(fuzz_input).find("not valid JSON"), std::string::npos);
  EXPECT_NE(errorOf(withKey(R"("frames": 1e999)")).find("not valid JSON"), std::string::npos);
}

TEST(SceneLoader, UnknownSceneNameListsKnownOnes) {
  try {
    scene::loadScene("no_such_scene");
    FAIL() << "expected SceneError";
  } catch (const scene::SceneError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("unknown scene 'no_such_scene'"), std::string::npos) << what;
    EXPECT_NE(what.find("dambreak"), std::string::npos) << what;
  }
  EXPECT_THROW(scene::loadScene("/nonexistent/file.json"), scene::SceneError);
}

TEST(SceneLoader, WaterRegionTooSmallForTheParticlesFailsToFill) {
  const sph::Scene s = scene::parseScene(
      R"({"box": {"min": [0,0,0], "max": [1,1,1]}, "water": {"min": [0,0,0], "max": [0.1,0.1,0.1]}})", "small.json");
  sph::ParticleSet p;
  EXPECT_THROW(sph::fillWater(s, sph::Level{0}, *sph::makeFluidSolver(s), p), std::invalid_argument);
}

TEST(SceneLoader, MethodAdaptiveSettingsAndGazeRecordingAreRead) {
  const sph::Scene s = scene::parseScene(withKey(R"("method": "hybrid", "gaze_recording": "x.gaze.csv",
                 "adaptive": {"gaze_radius": 0.07, "gaze_ring_radius": 0.1, "alpha": 0.5,
                              "surface_includes_walls": false})"),
                                         "test.json");
  EXPECT_EQ(s.method, "hybrid");
  EXPECT_EQ(s.gaze_recording, "x.gaze.csv");
  EXPECT_DOUBLE_EQ(s.adaptive.gaze_radius, 0.07);
  EXPECT_DOUBLE_EQ(s.adaptive.gaze_ring_radius, 0.1);
  EXPECT_DOUBLE_EQ(s.adaptive.alpha, 0.5);
  EXPECT_FALSE(s.adaptive.surface_includes_walls);
  EXPECT_DOUBLE_EQ(s.adaptive.threshold, 0.225);  // untouched: the thesis value
}

TEST(SceneLoader, BadMethodAndAdaptiveSettingsAreNamed) {
  std::string e = errorOf(withKey(R"("method": "eye")"));
  EXPECT_NE(e.find("'method'"), std::string::npos) << e;
  e = errorOf(withKey(R"("adaptive": {"gaze_radius": -1})"));
  EXPECT_NE(e.find("gaze_radius"), std::string::npos) << e;
  e = errorOf(withKey(R"("adaptive": {"gaze_radius": 0.1, "gaze_ring_radius": 0.05})"));
  EXPECT_NE(e.find("gaze_ring_radius"), std::string::npos) << e;
  e = errorOf(withKey(R"("adaptive": {"radius": 0.1})"));
  EXPECT_NE(e.find("'adaptive.radius'"), std::string::npos) << e;
  e = errorOf(withKey(R"("adaptive": {"surface_includes_walls": 1})"));
  EXPECT_NE(e.find("surface_includes_walls"), std::string::npos) << e;
  // One wording with the simulation parameters: the key, then what it takes.
  e = errorOf(withKey(R"("adaptive": {"gaze_radius": 3})"));
  EXPECT_NE(e.find("key 'adaptive.gaze_radius': must be a number in [0, 2]"), std::string::npos) << e;
  e = errorOf(withKey(R"("adaptive": {"foveated_thin_level": 1.5})"));
  EXPECT_NE(e.find("key 'adaptive.foveated_thin_level': must be an integer in [0, 7]"), std::string::npos) << e;
  // A setting in the other block is named with where it belongs.
  e = errorOf(withKey(R"("adaptive": {"pbf_omega": 0.5})"));
  EXPECT_NE(e.find("'adaptive.pbf_omega': unknown parameter (a simulation parameter: it belongs in 'params')"),
            std::string::npos)
      << e;
  e = errorOf(withKey(R"("params": {"alpha": 0.5})"));
  EXPECT_NE(e.find("'params.alpha': unknown parameter (an adaptive setting"), std::string::npos) << e;
}

TEST(SceneLoader, AdaptiveSettingsTakeTheirTypeAndFormerNames) {
  const sph::Scene s =
      scene::parseScene(withKey(R"("adaptive": {"foveated_thin_level": 2, "gaze_ring": 0.12})"), "test.json");
  EXPECT_EQ(s.adaptive.foveated_thin_level, 2);
  EXPECT_DOUBLE_EQ(s.adaptive.gaze_ring_radius, 0.12);
}

// Adding a setting is one row of the settings table: the loader reads a row registered by a test.
TEST(SceneLoader, ASettingAddedToTheTableIsRead) {
  const sph_test::ScopedSetting added(sph_test::testOnlySetting());
  const sph::Scene s = scene::parseScene(withKey(R"("adaptive": {"test_only_hold_s": 2.5})"), "test.json");
  EXPECT_DOUBLE_EQ(s.adaptive.foveated_merge_hold_s, 2.5);
  const std::string e = errorOf(withKey(R"("adaptive": {"test_only_hold_s": 6})"));
  EXPECT_NE(e.find("key 'adaptive.test_only_hold_s': must be a number in [0, 5]"), std::string::npos) << e;
}

TEST(SceneLoader, ShippedScenesNameAGazeRecordingThatExists) {
  for (const auto& name : scene::listScenes(scene::defaultSceneDir())) {
    const sph::Scene s = scene::loadScene(name);
    ASSERT_FALSE(s.gaze_recording.empty()) << name;
    EXPECT_TRUE(std::filesystem::exists(s.gaze_recording)) << s.gaze_recording;
  }
}
