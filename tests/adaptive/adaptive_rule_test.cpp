// Adaptive methods as rules (adaptive/adaptive_rule.h): a rule of its own runs through the
// controller without the method registry, with the shared split and merge; the registry maps
// every adaptive method to its rule and regular to none.
#include "sph/adaptive/adaptive_rule.h"

#include <gtest/gtest.h>

#include "adaptive_test_util.h"

namespace {

using adaptive_test::cameraOf;
using adaptive_test::poolScene;

// A method for the test only: split every particle in the left half of the box, merge the rest.
class LeftHalfRule : public sph::AdaptiveRule {
 public:
  explicit LeftHalfRule(double middle_x) : middle_x_(middle_x) {}
  sph::Method method() const override { return sph::Method::Surface; }  // what the frames call it
  sph::Level coarsest(int /*levels*/) const override { return sph::Level{1}; }
  void step(sph::Simulation& sim, const sph::RuleInput& in, sph::LevelChanges& changes,
            sph::AdaptiveStats& stats) override {
    const sph::ParticleSet& p = sim.particles();
    const std::span<std::int8_t> decisions = changes.decisions(p.size());
    sph::DecisionCounts wanted;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const bool left = p.position[i].x() < middle_x_;
      decisions[i] = left ? sph::kSplit : sph::kMerge;
      wanted.split_wanted += left && sph::wantsSplit(decisions[i], p.level[i]);
      wanted.merge_wanted += !left && sph::wantsMerge(decisions[i], p.level[i], coarsest(in.levels));
    }
    const sph::SplitMergeCounts counts = changes.apply(sim, wanted, coarsest(in.levels), stragglerReach());
    stats.splits = counts.splits;
    stats.merges = counts.merges;
  }

 private:
  double middle_x_;
};

TEST(AdaptiveRule, ARuleOfItsOwnRunsWithoutTheRegistry) {
  const sph::Scene scene = poolScene(0.5, 0.5, 648);  // two layers of L1
  sph::Simulation sim(scene, sph::Level{1});
  const double mass = sim.particles().totalMass();
  auto controller = std::make_unique<sph::AdaptiveController>(std::make_unique<LeftHalfRule>(0.25), scene.params.levels,
                                                              sph::AdaptiveConfig{}, cameraOf(scene));
  sph::AdaptiveController* rule_controller = controller.get();
  sim.setAdaptiveStep(std::move(controller));
  for (int s = 0; s < 5; ++s) sim.step();
  EXPECT_GT(rule_controller->lastStats().splits + sim.particles().countOf(sph::Level{0}), 0);
  const sph::ParticleSet& p = sim.particles();
  int left_l1 = 0, right_l0 = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    // Away from the middle, where water crosses it between a decision and the next.
    if (p.position[i].x() < 0.2) left_l1 += p.level[i] == sph::Level{1};
    if (p.position[i].x() > 0.3) right_l0 += p.level[i] == sph::Level{0};
  }
  EXPECT_EQ(left_l1, 0) << "the left half should be all L0";
  EXPECT_EQ(right_l0, 0) << "the right half should be all L1";
  EXPECT_DOUBLE_EQ(p.totalMass(), mass);
}

TEST(AdaptiveRule, TheRegistryMapsEveryAdaptiveMethodToItsRule) {
  EXPECT_EQ(sph::makeAdaptiveRule(sph::Method::Regular), nullptr);
  for (const std::string& name : sph::methodNames()) {
    sph::Method m{};
    ASSERT_TRUE(sph::methodByName(name, m));
    EXPECT_EQ(sph::adapts(m), sph::makeAdaptiveRule(m) != nullptr) << name;
    if (!sph::adapts(m)) continue;
    const auto rule = sph::makeAdaptiveRule(m);
    ASSERT_NE(rule, nullptr) << name;
    EXPECT_EQ(rule->method(), m) << name;
    EXPECT_EQ(sph::startLevel(m, 6), rule->coarsest(6)) << name;
  }
  EXPECT_EQ(sph::coarsestLevel(sph::Method::Foveated, 6), sph::Level{5});
  EXPECT_EQ(sph::coarsestLevel(sph::Method::Hybrid, 6), sph::Level{1});
  // What the server asks of a method by its traits, never by its name.
  EXPECT_TRUE(sph::sizesByAcuity(sph::Method::Foveated));
  EXPECT_FALSE(sph::sizesByAcuity(sph::Method::Hybrid));
  EXPECT_TRUE(sph::refinesGazeCircle(sph::Method::Gaze));
  EXPECT_TRUE(sph::refinesGazeCircle(sph::Method::Hybrid));
  EXPECT_FALSE(sph::refinesGazeCircle(sph::Method::Foveated));
  EXPECT_THROW(sph::AdaptiveController(sph::Method::Regular, 4, {}, sph::ScreenCamera{}), std::invalid_argument);
}

}  // namespace
