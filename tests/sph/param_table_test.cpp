// The settings table (sph/param_table.h) is the one place a setting is declared, simulation
// parameter or adaptive setting: the docs' tables are generated from it, and its checks are what
// the scene loader, both validates and the command line apply; a row registered at run time is
// read like the built-in ones.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sph/param_table.h"
#include "support/test_setting.h"

namespace {

std::string docsTable() {
  std::ifstream in(std::string(SPH_DOCS_DIR) + "/parameters.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string all = text.str();
  const std::string begin = "<!-- parameter-table:begin -->\n";
  const std::size_t from = all.find(begin);
  const std::size_t to = all.find("<!-- parameter-table:end -->");
  if (from == std::string::npos || to == std::string::npos) return "(no parameter table markers in docs/parameters.md)";
  return all.substr(from + begin.size(), to - from - begin.size());
}

TEST(ParamTable, TheDocsTableIsTheCodesTable) {
  EXPECT_EQ(docsTable(), sph::parameterTableMarkdown())
      << "docs/parameters.md's parameter table differs from server/sph/param_table.cpp: put the output of "
         "`build/bin/sph_bench --parameter-table` between its markers";
}

TEST(ParamTable, EveryKeyAndAliasIsOneParameter) {
  std::set<std::string> names;
  for (const sph::ParamSpec& spec : sph::parameterTable()) {
    EXPECT_TRUE(names.insert(spec.key).second) << spec.key;
    EXPECT_EQ(sph::findParameter(spec.key), &spec);
    if (spec.alias != nullptr) {
      EXPECT_TRUE(names.insert(spec.alias).second) << spec.alias;
      EXPECT_EQ(sph::findParameter(spec.alias), &spec);
    }
  }
  EXPECT_EQ(sph::findParameter("no_such_parameter"), nullptr);
}

TEST(ParamTable, EveryPresetsDefaultsPassTheTable) {
  for (const std::string& name : sph::presetNames()) {
    sph::SimParams p;
    ASSERT_TRUE(sph::presetByName(name, p));
    EXPECT_NO_THROW(p.validate()) << name;
    for (const sph::ParamSpec& spec : sph::parameterTable()) {
      if (!spec.isAdaptive()) {
        EXPECT_EQ(spec.check(spec.get(p)), "") << spec.key;
      }
    }
  }
  const sph::AdaptiveConfig adaptive;
  EXPECT_NO_THROW(adaptive.validate());
  for (const sph::ParamSpec& spec : sph::parameterTable()) {
    if (spec.isAdaptive()) {
      EXPECT_EQ(spec.check(spec.get(adaptive)), "") << spec.key;
    }
  }
}

// `spec` just outside its range in `holder`, then `holder.validate()`: the error names the key.
template <class Holder>
void expectValidateNames(const sph::ParamSpec& spec, Holder holder) {
  spec.set(holder, std::isinf(spec.max) ? spec.min - 1.0 : spec.max + 1.0);
  try {
    holder.validate();
    ADD_FAILURE() << spec.key << " out of range passed validate";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(std::string("parameter '") + spec.key + "' must be " + spec.accepts()),
              std::string::npos)
        << e.what();
  }
}

TEST(ParamTable, ValidateNamesTheParameterOutOfItsRange) {
  for (const sph::ParamSpec& spec : sph::parameterTable()) {
    // Gravity takes any finite number; a flag's field holds nothing but true and false.
    if ((std::isinf(spec.max) && std::isinf(spec.min)) || spec.isFlag()) continue;
    if (spec.isAdaptive()) {
      expectValidateNames(spec, sph::AdaptiveConfig{});
    } else {
      expectValidateNames(spec, sph::pbfPreset());
    }
  }
}

TEST(ParamTable, AdaptiveSettingsAreRowsOfTheirType) {
  const sph::ParamSpec& level = *sph::findParameter("foveated_thin_level");
  EXPECT_TRUE(level.isAdaptive());
  EXPECT_TRUE(level.isInteger());
  EXPECT_EQ(level.check(1.5), "must be an integer in [0, 7]");
  EXPECT_TRUE(sph::findParameter("surface_includes_walls")->isFlag());
  EXPECT_EQ(sph::findParameter("gaze_ring"), sph::findParameter("gaze_ring_radius"));
  EXPECT_FALSE(sph::findParameter("pbf_omega")->isAdaptive());
  // A row reads and writes its own struct only.
  sph::SimParams p;
  EXPECT_THROW((void)level.get(p), std::logic_error);
  const sph::AdaptiveConfig c =
      sph::withAdaptiveSettings(sph::AdaptiveConfig{}, {{"foveated_thin_level", 2.0}, {"gaze_ring", 0.2}});
  EXPECT_EQ(c.foveated_thin_level, 2);
  EXPECT_EQ(c.gaze_ring_radius, 0.2);
  EXPECT_THROW(sph::withAdaptiveSettings(sph::AdaptiveConfig{}, {{"pbf_omega", 0.5}}), std::invalid_argument);
  EXPECT_THROW(sph::withAdaptiveSettings(sph::AdaptiveConfig{}, {{"gaze_radius", 0.5}}), std::invalid_argument);
}

TEST(ParamTable, ChecksTellTypeAndRange) {
  const sph::ParamSpec& omega = *sph::findParameter("pbf_omega");
  EXPECT_EQ(omega.check(1.0), "");
  EXPECT_EQ(omega.check(0.0), "must be a number in (0, 1]");
  EXPECT_NE(omega.check(std::numeric_limits<double>::quiet_NaN()), "");
  const sph::ParamSpec& iterations = *sph::findParameter("pbf_iterations");
  EXPECT_EQ(iterations.check(2.5), "must be an integer in [1, 100]");
  EXPECT_EQ(sph::findParameter("dfsph_conjugate_gradients")->check(0.5), "must be true or false");
}

TEST(ParamTable, CommandLineSettingsReadByKeyOrAlias) {
  std::map<std::string, double> out;
  std::string error;
  EXPECT_TRUE(sph::parseParameterSetting("pbf_iterations=3", out, error)) << error;
  EXPECT_TRUE(sph::parseParameterSetting("conjugate_gradients=false", out, error)) << error;
  EXPECT_EQ(out.at("pbf_iterations"), 3.0);
  EXPECT_EQ(out.at("dfsph_conjugate_gradients"), 0.0);
  EXPECT_TRUE(sph::parseParameterSetting("surface_includes_walls=false", out, error)) << error;
  EXPECT_TRUE(sph::parseParameterSetting("gaze_ring=0.1", out, error)) << error;
  EXPECT_EQ(out.at("surface_includes_walls"), 0.0);
  EXPECT_EQ(out.at("gaze_ring_radius"), 0.1);
  for (const char* bad : {"pbf_iterations", "nosuch=1", "pbf_iterations=3x", "pbf_iterations=0", "pbf_omega=nan",
                          "foveated_thin_level=1.5"}) {
    EXPECT_FALSE(sph::parseParameterSetting(bad, out, error)) << bad;
    EXPECT_FALSE(error.empty());
  }
  EXPECT_FALSE(sph::parseParameterSetting("alpha=-1", out, error));
  EXPECT_EQ(error, "alpha must be a number in [0, 1000000]");
}

// Adding a setting is one row: a row registered here is found, checked, listed in --help and the
// docs' table, and sets its field (tests/scene and tests/net: the loader and set_parameters too).
TEST(ParamTable, ARegisteredRowIsASettingEverywhere) {
  {
    const sph_test::ScopedSetting added(sph_test::testOnlySetting());
    EXPECT_THROW(sph::registerParameter(sph_test::testOnlySetting()), std::invalid_argument);
    ASSERT_NE(sph::findParameter("test_only_hold_s"), nullptr);
    EXPECT_NE(sph::parameterHelpText(true).find("test_only_hold_s"), std::string::npos);
    EXPECT_EQ(sph::parameterHelpText(false).find("test_only_hold_s"), std::string::npos);
    EXPECT_NE(sph::parameterTableMarkdown().find("| `test_only_hold_s` | foveated | a number in [0, 5] | s | 0 |"),
              std::string::npos);
    std::map<std::string, double> out;
    std::string error;
    EXPECT_TRUE(sph::parseParameterSetting("test_only_hold_s=2", out, error)) << error;
    EXPECT_FALSE(sph::parseParameterSetting("test_only_hold_s=6", out, error));
    EXPECT_EQ(error, "test_only_hold_s must be a number in [0, 5]");
    EXPECT_EQ(sph::withAdaptiveSettings(sph::AdaptiveConfig{}, out).foveated_merge_hold_s, 2.0);
    sph::AdaptiveConfig c;
    c.foveated_merge_hold_s = 6.0;  // in foveated_merge_hold_s's own range, outside the test row's
    EXPECT_THROW(c.validate(), std::invalid_argument);
  }
  EXPECT_EQ(sph::findParameter("test_only_hold_s"), nullptr);
  EXPECT_FALSE(sph::unregisterParameter("test_only_hold_s"));
}

}  // namespace
