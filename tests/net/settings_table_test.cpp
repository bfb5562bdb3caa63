// set_parameters reads the settings table (sph/param_table.h): simulation parameters and adaptive
// settings by one check and one wording, and a row a test adds is a setting a client can set.
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "app/control_executor.h"
#include "app/sim_session.h"
#include "support/test_setting.h"

namespace {

// A session on tests/net's tiny pool, and set_parameters applied to it in-process.
struct Session {
  app::SimSession session{SPH_NET_TEST_SCENE_DIR, {}, nullptr};
  app::RunSettings settings;
  app::ControlTarget target{session, settings, nullptr};
  Session() { session.load("tiny_pool", sph::Method::Gaze); }

  gsph::v1::ControlReply set(std::initializer_list<std::pair<const std::string, double>> values) {
    gsph::v1::Control request;
    for (const auto& [key, value] : values) (*request.mutable_set_parameters()->mutable_values())[key] = value;
    app::ControlEffects effects;
    return app::executeControl(request, target, effects);
  }
};

TEST(SettingsTable, SetParametersChecksAdaptiveSettingsByTheTable) {
  Session s;
  gsph::v1::ControlReply r = s.set({{"foveated_thin_level", 2.0}, {"gaze_ring", 0.1}});
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(s.session.config().foveated_thin_level, 2);
  EXPECT_EQ(r.status().parameters().at("gaze_ring_radius"), 0.1);
  EXPECT_EQ(r.status().parameters().count("gaze_ring"), 0u) << "a former name is no entry of its own";

  r = s.set({{"foveated_thin_level", 1.5}});
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.error_code(), gsph::v1::ERROR_CODE_BAD_PARAMETER);
  EXPECT_EQ(r.error(), "parameter 'foveated_thin_level' must be an integer in [0, 7]");
  r = s.set({{"gaze_radius", 0.06}, {"surface_includes_walls", 0.5}});
  EXPECT_EQ(r.error(), "parameter 'surface_includes_walls' must be 0 or 1");
  EXPECT_EQ(s.session.config().gaze_radius, sph::AdaptiveConfig{}.gaze_radius) << "a refused request changed a value";
  r = s.set({{"no_such_setting", 1.0}});
  EXPECT_NE(r.error().find("unknown parameter 'no_such_setting'"), std::string::npos) << r.error();
}

// Adding a setting is one row: set_parameters and the status read a row registered by a test.
TEST(SettingsTable, ASettingAddedToTheTableIsSetByAClient) {
  const sph_test::ScopedSetting added(sph_test::testOnlySetting());
  Session s;
  gsph::v1::ControlReply r = s.set({{"test_only_hold_s", 2.0}});
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(s.session.config().foveated_merge_hold_s, 2.0);
  EXPECT_EQ(r.status().parameters().at("test_only_hold_s"), 2.0);
  r = s.set({{"test_only_hold_s", 6.0}});
  EXPECT_EQ(r.error(), "parameter 'test_only_hold_s' must be a number in [0, 5]");
  EXPECT_EQ(s.session.config().foveated_merge_hold_s, 2.0);
}

}  // namespace
