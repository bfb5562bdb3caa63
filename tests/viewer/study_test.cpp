// The study mode's pure parts: the study file's checks, the trial order from a seed, the answers'
// scoring, the binomial figures of the summary, and the output files' shape.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <sstream>

#include "binomial_stats.h"
#include "study_plan.h"
#include "study_results.h"
#include "study_trials.h"

namespace {

const char* kGood = R"({
  "name": "demo", "question": "two_interval", "scenes": ["dambreak", "wave"],
  "comparisons": [
    {"name": "fov", "reference": {"method": "regular"},
     "test": {"method": "foveated", "parameters": {"foveated_quality": 1.5}}},
    {"name": "gaze", "reference": {"method": "regular"}, "test": {"method": "gaze"}}],
  "interval_s": 3, "blank_s": 0.5, "repetitions": 4, "seed": 42})";

std::string refusal(const std::string& text) {
  try {
    viewer::parseStudyPlan(text, "study.json");
  } catch (const viewer::StudyFileError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(StudyPlan, AGoodFileParses) {
  const viewer::StudyPlan plan = viewer::parseStudyPlan(kGood, "study.json");
  EXPECT_EQ(plan.name, "demo");
  EXPECT_EQ(plan.scenes.size(), 2u);
  ASSERT_EQ(plan.comparisons.size(), 2u);
  EXPECT_EQ(plan.comparisons[0].test.method, gsph::v1::METHOD_FOVEATED);
  EXPECT_EQ(plan.comparisons[0].test.parameters.at("foveated_quality"), 1.5);
  EXPECT_EQ(plan.comparisons[0].test.label(), "foveated foveated_quality=1.5");
  EXPECT_EQ(plan.interval_s, 3.0);
  EXPECT_EQ(plan.repetitions, 4);
  ASSERT_TRUE(plan.seed.has_value());
  EXPECT_EQ(*plan.seed, 42u);
}

TEST(StudyPlan, BadFilesAreRefusedWithTheirReason) {
  const std::pair<std::string, std::string> cases[] = {
      {"{", "not valid JSON"},
      {"[]", "must be a JSON object"},
      {R"({"scenes": ["a"], "comparisons": []})", "\"name\""},
      {R"({"name": "x", "scenes": [], "comparisons": [{"reference": {"method": "regular"}, "test": {"method": "gaze"}}]})",
       "\"scenes\""},
      {R"({"name": "x", "scenes": ["a"], "comparisons": [{"reference": {"method": "regular"}, "test": {"method": "fast"}}]})",
       "unknown method \"fast\""},
      {R"({"name": "x", "scenes": ["a"], "comparisons": [{"reference": {"method": "regular"}}]})",
       "needs \"reference\" and \"test\""},
      {R"({"name": "x", "scenes": ["a"], "question": "which", "comparisons": [{"reference": {"method": "regular"}, "test": {"method": "gaze"}}]})",
       "\"question\""},
      {R"({"name": "x", "scenes": ["a"], "interval_s": 0, "comparisons": [{"reference": {"method": "regular"}, "test": {"method": "gaze"}}]})",
       "\"interval_s\" must be between"},
      {R"({"name": "x", "scenes": ["a"], "repetitions": 2.5, "comparisons": [{"reference": {"method": "regular"}, "test": {"method": "gaze"}}]})",
       "whole number"},
      {R"({"name": "x", "scenes": ["a"], "seed": -1, "comparisons": [{"reference": {"method": "regular"}, "test": {"method": "gaze"}}]})",
       "\"seed\""},
      {R"({"name": "x", "scenes": ["a"], "trials": 3, "comparisons": [{"reference": {"method": "regular"}, "test": {"method": "gaze"}}]})",
       "unknown key \"trials\""},
      {R"({"name": "x", "scenes": ["a"], "comparisons": [{"reference": {"method": "regular", "parameters": {"q": "hi"}}, "test": {"method": "gaze"}}]})",
       "parameter \"q\" must be a finite number"},
  };
  for (const auto& [text, reason] : cases) {
    const std::string why = refusal(text);
    EXPECT_NE(why.find("study.json: "), std::string::npos) << why;
    EXPECT_NE(why.find(reason), std::string::npos) << "for " << text << ": " << why;
  }
  EXPECT_NE(refusal("{}").find("\"name\""), std::string::npos);
  EXPECT_THROW(viewer::loadStudyPlan("/nonexistent/study.json"), viewer::StudyFileError);
}

TEST(StudyTrials, TheSeedFixesTheOrderAndEveryTrialIsThere) {
  const viewer::StudyPlan plan = viewer::parseStudyPlan(kGood, "study.json");
  const auto a = viewer::makeTrials(plan, 42);
  const auto b = viewer::makeTrials(plan, 42);
  const auto c = viewer::makeTrials(plan, 43);
  ASSERT_EQ(a.size(), 2u * 2u * 4u);
  std::string order_a, order_b, order_c;
  std::set<std::tuple<std::size_t, std::size_t, int>> seen;
  int reference_first = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    order_a += std::to_string(a[i].scene) + std::to_string(a[i].comparison) + viewer::orderText(a[i]);
    order_b += std::to_string(b[i].scene) + std::to_string(b[i].comparison) + viewer::orderText(b[i]);
    order_c += std::to_string(c[i].scene) + std::to_string(c[i].comparison) + viewer::orderText(c[i]);
    seen.insert({a[i].scene, a[i].comparison, a[i].repetition});
    EXPECT_FALSE(a[i].same()) << "two-interval trials show both conditions";
    reference_first += a[i].intervals[0] == viewer::Shown::kReference;
  }
  EXPECT_EQ(order_a, order_b);
  EXPECT_NE(order_a, order_c);
  EXPECT_EQ(seen.size(), a.size());
  EXPECT_GT(reference_first, 0);
  EXPECT_LT(reference_first, static_cast<int>(a.size()));
}

TEST(StudyTrials, SameDifferentTrialsAreSomeOfEach) {
  viewer::StudyPlan plan = viewer::parseStudyPlan(kGood, "study.json");
  plan.question = viewer::StudyQuestion::kSameDifferent;
  plan.repetitions = 20;
  const auto trials = viewer::makeTrials(plan, 5);
  ASSERT_EQ(trials.size(), 2u * 2u * 20u);
  std::set<std::string> orders;
  int same = 0;
  for (const auto& t : trials) {
    orders.insert(viewer::orderText(t));
    same += t.same();
  }
  EXPECT_EQ(orders, (std::set<std::string>{"RR", "RT", "TR", "TT"}));
  // About half "same" (binomially: 80 draws of one half stay within 20..60 but for p < 1e-5).
  EXPECT_GT(same, 20);
  EXPECT_LT(same, 60);
  const auto again = viewer::makeTrials(plan, 5);
  for (std::size_t i = 0; i < trials.size(); ++i) {
    EXPECT_STREQ(viewer::orderText(trials[i]), viewer::orderText(again[i]));
  }
}

TEST(StudyTrials, AnswersAreScoredByTheQuestion) {
  viewer::StudyTrial t;
  t.intervals = {viewer::Shown::kTest, viewer::Shown::kReference};
  EXPECT_TRUE(viewer::answerCorrect(viewer::StudyQuestion::kTwoInterval, t, 2));
  EXPECT_FALSE(viewer::answerCorrect(viewer::StudyQuestion::kTwoInterval, t, 1));
  EXPECT_TRUE(viewer::answerCorrect(viewer::StudyQuestion::kSameDifferent, t, 2));  // different
  t.intervals = {viewer::Shown::kTest, viewer::Shown::kTest};
  EXPECT_TRUE(viewer::answerCorrect(viewer::StudyQuestion::kSameDifferent, t, 1));  // same
  EXPECT_FALSE(viewer::answerCorrect(viewer::StudyQuestion::kSameDifferent, t, 3));
}

TEST(BinomialStats, WilsonIntervalMatchesPublishedValues) {
  // 8 of 10: 0.4902 .. 0.9433 (Newcombe 1998, method 3, as R's prop.test without correction gives).
  const viewer::Interval i = viewer::wilsonInterval95(8, 10);
  EXPECT_NEAR(i.low, 0.4902, 1e-4);
  EXPECT_NEAR(i.high, 0.9433, 1e-4);
  const viewer::Interval all = viewer::wilsonInterval95(10, 10);
  EXPECT_NEAR(all.high, 1.0, 1e-12);
  EXPECT_NEAR(all.low, 0.7225, 1e-4);
  const viewer::Interval none = viewer::wilsonInterval95(0, 0);
  EXPECT_EQ(none.low, 0.0);
  EXPECT_EQ(none.high, 1.0);
}

TEST(BinomialStats, ExactTestMatchesTheBinomialSums) {
  // Two-sided against one half: 2 * P(X >= k) for k above n / 2.
  EXPECT_NEAR(viewer::binomialTestP(8, 10, 0.5), 2.0 * 56.0 / 1024.0, 1e-12);
  EXPECT_NEAR(viewer::binomialTestP(10, 10, 0.5), 2.0 / 1024.0, 1e-12);
  EXPECT_NEAR(viewer::binomialTestP(5, 10, 0.5), 1.0, 1e-12);
  EXPECT_NEAR(viewer::binomialTestP(2, 10, 0.5), 2.0 * 56.0 / 1024.0, 1e-12);  // symmetric
  EXPECT_NEAR(viewer::binomialTestP(1, 2, 0.5), 1.0, 1e-12);
  EXPECT_EQ(viewer::binomialTestP(0, 0, 0.5), 1.0);
  // Against another chance the sum is over the outcomes no more likely than the observed one:
  // 3 of 4 at 0.25 -> P(3) + P(4) = 12/256 + 1/256.
  EXPECT_NEAR(viewer::binomialTestP(3, 4, 0.25), 13.0 / 256.0, 1e-12);
}

TEST(StudyResults, OneRowPerTrialAndOneSummaryRowPerComparison) {
  const viewer::StudyPlan plan = viewer::parseStudyPlan(kGood, "study.json");
  const auto trials = viewer::makeTrials(plan, 42);
  std::vector<viewer::TrialRecord> records;
  std::ostringstream csv;
  viewer::writeTrialHeader(csv);
  for (int i = 0; i < 4; ++i) {
    viewer::TrialRecord r;
    r.number = i + 1;
    r.trial = trials[static_cast<std::size_t>(i)];
    r.answer = 1;
    r.correct = viewer::answerCorrect(plan.question, r.trial, 1);
    r.intervals[0].frames = 10;
    r.intervals[0].gaze_tracking_frames = 5;
    r.intervals[0].gaze_x_sum = 2.5;
    r.intervals[0].gaze_y_sum = 2.0;
    r.intervals[0].gaze_xx_sum = 1.25;
    r.intervals[0].gaze_yy_sum = 0.8;
    records.push_back(r);
    viewer::writeTrialRow(csv, plan, 42, r);
  }
  std::istringstream lines(csv.str());
  std::string line;
  std::vector<std::string> rows;
  while (std::getline(lines, line)) rows.push_back(line);
  ASSERT_EQ(rows.size(), 5u);
  const auto columns = [](const std::string& s) { return std::count(s.begin(), s.end(), ',') + 1; };
  for (const auto& row : rows) EXPECT_EQ(columns(row), columns(rows[0])) << row;
  EXPECT_NE(rows[1].find(",42,"), std::string::npos) << "the seed is in every row";
  EXPECT_NE(rows[1].find(",0.500,0.5000,0.4000,0.0000,"), std::string::npos) << rows[1];
  std::ostringstream summary;
  viewer::writeSummary(summary, plan, 42, records);
  std::istringstream s(summary.str());
  std::vector<std::string> srows;
  while (std::getline(s, line)) srows.push_back(line);
  ASSERT_EQ(srows.size(), 1u + plan.comparisons.size());
  EXPECT_EQ(srows[0].rfind("study,seed,question,comparison,trials,correct", 0), 0u);
}

}  // namespace
