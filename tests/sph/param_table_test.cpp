// The parameter table (sph/param_table.h) is the one place a parameter is declared: the docs'
// table is generated from it, and its checks are what the scene loader, validate and the command
// line apply.
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

namespace {

std::string docsTable() {
  std::ifstream in(std::string(SPH_DOCS_DIR) + "/fluids.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string all = text.str();
  const std::string begin = "<!-- parameter-table:begin -->\n";
  const std::size_t from = all.find(begin);
  const std::size_t to = all.find("<!-- parameter-table:end -->");
  if (from == std::string::npos || to == std::string::npos) return "(no parameter table markers in docs/fluids.md)";
  return all.substr(from + begin.size(), to - from - begin.size());
}

TEST(ParamTable, TheDocsTableIsTheCodesTable) {
  EXPECT_EQ(docsTable(), sph::parameterTableMarkdown())
      << "docs/fluids.md's parameter table differs from server/sph/param_table.cpp: put the output of "
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
    for (const sph::ParamSpec& spec : sph::parameterTable()) EXPECT_EQ(spec.check(spec.get(p)), "") << spec.key;
  }
}

TEST(ParamTable, ValidateNamesTheParameterOutOfItsRange) {
  for (const sph::ParamSpec& spec : sph::parameterTable()) {
    // Gravity takes any finite number; a flag's field holds nothing but true and false.
    if ((std::isinf(spec.max) && std::isinf(spec.min)) || spec.isFlag()) continue;
    sph::SimParams p = sph::pbfPreset();
    spec.set(p, std::isinf(spec.max) ? spec.min - 1.0 : spec.max + 1.0);
    try {
      p.validate();
      ADD_FAILURE() << spec.key << " out of range passed validate";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("'") + spec.key + "'"), std::string::npos) << e.what();
    }
  }
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
  for (const char* bad : {"pbf_iterations", "nosuch=1", "pbf_iterations=3x", "pbf_iterations=0", "pbf_omega=nan"}) {
    EXPECT_FALSE(sph::parseParameterSetting(bad, out, error)) << bad;
    EXPECT_FALSE(error.empty());
  }
}

}  // namespace
