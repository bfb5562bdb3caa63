// The foveated method's rules one at a time (adaptive/foveated_rules.h), on the figures a
// decision measures for one particle and, for the shallow rule, on a handful of neighbours.
#include "sph/adaptive/foveated_rules.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

// Four levels' widths in finest widths: each level twice the mass, 2^(1/3) the width.
const float kWidth[] = {1.0f, std::cbrt(2.0f), std::cbrt(4.0f), 2.0f};
constexpr int kCoarsest = 3;
constexpr float kMargin = 1.25f;
// Their supports in metres, each 2^(1/3) the one below's: the coarsest's is the hidden depth the
// tests use, 0.12 m.
const float kSupport[] = {0.06f, 0.06f * std::cbrt(2.0f), 0.06f * std::cbrt(4.0f), 0.12f};

TEST(FoveatedRules, AcuityTakesTheCoarsestLevelTheEyeAllowsAndWaitsForTheMarginToMerge) {
  EXPECT_EQ(sph::acuityBounds(1.0f, kWidth, kCoarsest, kMargin).target, 0);
  const sph::LevelBounds b = sph::acuityBounds(1.3f, kWidth, kCoarsest, kMargin);  // L1 (1.26) fits
  EXPECT_EQ(b.target, 1);
  EXPECT_EQ(b.merge_upto, 0) << "1.26 x 1.25 > 1.3: no merge into L1 yet";
  const sph::LevelBounds wide = sph::acuityBounds(100.0f, kWidth, kCoarsest, kMargin);
  EXPECT_EQ(wide.target, kCoarsest);
  EXPECT_EQ(wide.merge_upto, kCoarsest);
  EXPECT_EQ(wide.eye_margin, kCoarsest);
}

TEST(FoveatedRules, HiddenWaterMayGoCoarsestAndMergesPastTheMarginsDepth) {
  sph::LevelBounds b = sph::acuityBounds(1.0f, kWidth, kCoarsest, kMargin);
  sph::hiddenRule(b, 0.10f, 0.12f, kSupport, 1.0f, 0.5f, kMargin, kCoarsest);
  EXPECT_EQ(b.target, 0) << "not deep enough";
  sph::hiddenRule(b, 0.13f, 0.12f, kSupport, 1.0f, 0.5f, kMargin, kCoarsest);
  EXPECT_EQ(b.target, kCoarsest);
  EXPECT_EQ(b.merge_upto, 0) << "0.13 < 0.12 x 1.25";
  sph::hiddenRule(b, 0.16f, 0.12f, kSupport, 1.0f, 0.5f, kMargin, kCoarsest);
  EXPECT_EQ(b.merge_upto, kCoarsest);
}

TEST(FoveatedRules, HiddenWaterTakesTheCoarsestLevelWhoseSupportItsDepthCovers) {
  // Six levels: L4's support is 0.151 m, L5's 0.190 m, deeper than the hidden depth.
  const float support[] = {0.06f, 0.0756f, 0.0952f, 0.12f, 0.151f, 0.190f};
  constexpr int kSixLevels = 5;
  sph::LevelBounds b = sph::acuityBounds(1.0f, kWidth, kCoarsest, kMargin);
  sph::hiddenRule(b, 0.13f, 0.12f, support, 1.0f, 0.5f, kMargin, kSixLevels);
  EXPECT_EQ(b.target, 3) << "L4's support would reach the surface";
  sph::hiddenRule(b, 0.16f, 0.12f, support, 1.0f, 0.5f, kMargin, kSixLevels);
  EXPECT_EQ(b.target, 4);
  EXPECT_EQ(b.merge_upto, 3) << "0.16 < 0.151 x 1.25: merges make L3 at most";
  sph::hiddenRule(b, 0.3f, 0.12f, support, 1.0f, 0.5f, kMargin, kSixLevels);
  EXPECT_EQ(b.target, kSixLevels);
  EXPECT_EQ(b.merge_upto, kSixLevels);
  sph::LevelBounds eye{kSixLevels, kSixLevels, kSixLevels};
  sph::hiddenRule(eye, 0.13f, 0.12f, support, 1.0f, 0.5f, kMargin, kSixLevels);
  EXPECT_EQ(eye.target, kSixLevels) << "the depth never makes water finer than the eye asks";
}

TEST(FoveatedRules, ALayerIsNeverHidden) {
  sph::LevelBounds b = sph::acuityBounds(1.0f, kWidth, kCoarsest, kMargin);
  sph::hiddenRule(b, 0.5f, 0.12f, kSupport, 0.3f, 0.5f, kMargin, kCoarsest);
  EXPECT_EQ(b.target, 0) << "a sheet as deep as it is wide is still a sheet";
  sph::hiddenRule(b, 0.5f, 0.12f, kSupport, 0.55f, 0.5f, kMargin, kCoarsest);
  EXPECT_EQ(b.target, kCoarsest);
  EXPECT_EQ(b.merge_upto, 0) << "0.55 < 0.5 x 1.25: no merge yet";
}

TEST(FoveatedRules, GradedKeepsAStepAboveTheFinestNeighbour) {
  sph::LevelBounds b{kCoarsest, kCoarsest, kCoarsest};
  sph::gradedRule(b, 0, 0, 1);
  EXPECT_EQ(b.target, 1);
  EXPECT_EQ(b.merge_upto, 1);
  sph::LevelBounds far{kCoarsest, kCoarsest, kCoarsest};
  sph::gradedRule(far, 2, 1, 1);  // L2 beside it, L1 within a merged particle's reach
  EXPECT_EQ(far.target, 3);
  EXPECT_EQ(far.merge_upto, 2);
  sph::LevelBounds wide{kCoarsest, kCoarsest, kCoarsest};
  sph::gradedRule(wide, 0, 0, 2);  // a step of two levels: L2 may border L0
  EXPECT_EQ(wide.target, 2);
  EXPECT_EQ(wide.merge_upto, 2);
}

TEST(FoveatedRules, ThinWaterStaysAtTheThinLevel) {
  sph::LevelBounds b{kCoarsest, kCoarsest, kCoarsest};
  sph::thinRule(b, 0.45f, 0.4f, kMargin, 1);
  EXPECT_EQ(b.target, kCoarsest) << "0.45 is not thin";
  EXPECT_EQ(b.merge_upto, 1) << "but 0.45 < 0.4 x 1.25: no merge past the thin level";
  sph::thinRule(b, 0.3f, 0.4f, kMargin, 1);
  EXPECT_EQ(b.target, 1);
  EXPECT_FALSE(sph::shallowCounts(b, 1));
}

Eigen::Matrix3f momentOf(const std::vector<Eigen::Vector3f>& offsets) {
  Eigen::Matrix3f m = Eigen::Matrix3f::Zero();
  for (const auto& r : offsets) m += r * r.transpose();
  return m;
}

TEST(FoveatedRules, OneLayerOfNeighboursIsShallowABallIsNot) {
  // Six neighbours in one horizontal layer, then the six of a ball, then the five of a half ball.
  const std::vector<Eigen::Vector3f> layer = {{1, 0, 0},  {-1, 0, 0},      {0, 0, 1},
                                              {0, 0, -1}, {0.7f, 0, 0.7f}, {-0.7f, 0, -0.7f}};
  const std::vector<Eigen::Vector3f> ball = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const std::vector<Eigen::Vector3f> half = {{1, 0, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  EXPECT_LT(sph::neighbourSpread(momentOf(layer), 1.0f), 0.01f);
  EXPECT_GT(sph::neighbourSpread(momentOf(ball), 1.0f), 0.99f);
  EXPECT_GT(sph::neighbourSpread(momentOf(half), 1.0f), 0.7f) << "a free surface is not shallow";
  EXPECT_EQ(sph::neighbourSpread(Eigen::Matrix3f::Zero(), 1.0f), 0.0f) << "no neighbours: a drop";
  sph::LevelBounds b{kCoarsest, kCoarsest, kCoarsest};
  ASSERT_TRUE(sph::shallowCounts(b, 1));
  sph::shallowRule(b, sph::neighbourSpread(momentOf(layer), 0.5f * kMargin), 0.5f, kMargin, 1);
  EXPECT_EQ(b.target, 1);
  EXPECT_EQ(b.merge_upto, 1);
}

}  // namespace
