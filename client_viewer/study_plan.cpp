#include "study_plan.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

namespace viewer {

namespace {

using nlohmann::json;

constexpr double kMaxIntervalS = 600.0;
constexpr int kMaxRepetitions = 1000;

constexpr gsph::v1::Method kMethods[] = {gsph::v1::METHOD_REGULAR, gsph::v1::METHOD_SURFACE, gsph::v1::METHOD_GAZE,
                                         gsph::v1::METHOD_HYBRID, gsph::v1::METHOD_FOVEATED};

[[noreturn]] void fail(const std::string& source, const std::string& what) {
  throw StudyFileError(source + ": " + what);
}

double number(const json& j, const char* key, double fallback, double lo, double hi, const std::string& source) {
  if (!j.contains(key)) return fallback;
  const json& v = j.at(key);
  if (!v.is_number()) fail(source, std::string("\"") + key + "\" must be a number");
  const double x = v.get<double>();
  if (!std::isfinite(x) || x < lo || x > hi) {
    std::ostringstream why;
    why << "\"" << key << "\" must be between " << lo << " and " << hi << " (got " << x << ")";
    fail(source, why.str());
  }
  return x;
}

StudyCondition condition(const json& j, const std::string& where, const std::string& source) {
  if (!j.is_object()) fail(source, where + " must be an object with a \"method\"");
  if (!j.contains("method") || !j.at("method").is_string()) fail(source, where + " needs \"method\" (a string)");
  StudyCondition c;
  const std::string name = j.at("method").get<std::string>();
  for (const gsph::v1::Method m : kMethods) {
    if (name == studyMethodName(m)) c.method = m;
  }
  if (c.method == gsph::v1::METHOD_UNSPECIFIED) {
    fail(source, where + ": unknown method \"" + name + "\" (known: regular, surface, gaze, hybrid, foveated)");
  }
  if (j.contains("parameters")) {
    const json& p = j.at("parameters");
    if (!p.is_object()) fail(source, where + ": \"parameters\" must be an object of numbers");
    for (const auto& [key, value] : p.items()) {
      if (!value.is_number() || !std::isfinite(value.get<double>())) {
        fail(source, where + ": parameter \"" + key + "\" must be a finite number");
      }
      c.parameters[key] = value.get<double>();
    }
  }
  for (const auto& [key, value] : j.items()) {
    if (key != "method" && key != "parameters") fail(source, where + ": unknown key \"" + key + "\"");
  }
  return c;
}

}  // namespace

std::string StudyCondition::label() const {
  std::string text = studyMethodName(method) != nullptr ? studyMethodName(method) : "?";
  for (const auto& [key, value] : parameters) {
    std::ostringstream v;
    v << value;
    text += " " + key + "=" + v.str();
  }
  return text;
}

const char* questionName(StudyQuestion question) {
  return question == StudyQuestion::kTwoInterval ? "two_interval" : "same_different";
}

const char* studyMethodName(gsph::v1::Method method) {
  switch (method) {
    case gsph::v1::METHOD_REGULAR:
      return "regular";
    case gsph::v1::METHOD_SURFACE:
      return "surface";
    case gsph::v1::METHOD_GAZE:
      return "gaze";
    case gsph::v1::METHOD_HYBRID:
      return "hybrid";
    case gsph::v1::METHOD_FOVEATED:
      return "foveated";
    default:
      return nullptr;
  }
}

StudyPlan parseStudyPlan(const std::string& text, const std::string& source) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    fail(source, std::string("not valid JSON: ") + e.what());
  }
  if (!j.is_object()) fail(source, "the study must be a JSON object");
  static const std::set<std::string> kKeys{"name",       "question", "preset",      "scenes", "comparisons",
                                           "interval_s", "blank_s",  "repetitions", "seed",   "description"};
  for (const auto& [key, value] : j.items()) {
    if (kKeys.count(key) == 0) fail(source, "unknown key \"" + key + "\"");
  }
  StudyPlan plan;
  if (!j.contains("name") || !j.at("name").is_string() || j.at("name").get<std::string>().empty()) {
    fail(source, "\"name\" (a non-empty string) is missing");
  }
  plan.name = j.at("name").get<std::string>();
  const std::string question = j.value("question", std::string("two_interval"));
  if (question == "two_interval") {
    plan.question = StudyQuestion::kTwoInterval;
  } else if (question == "same_different") {
    plan.question = StudyQuestion::kSameDifferent;
  } else {
    fail(source, "\"question\" must be \"two_interval\" or \"same_different\" (got \"" + question + "\")");
  }
  if (j.contains("preset")) {
    if (!j.at("preset").is_string()) fail(source, "\"preset\" must be a string");
    plan.preset = j.at("preset").get<std::string>();
  }
  if (!j.contains("scenes") || !j.at("scenes").is_array() || j.at("scenes").empty()) {
    fail(source, "\"scenes\" must be a non-empty list of scene names");
  }
  for (const json& s : j.at("scenes")) {
    if (!s.is_string() || s.get<std::string>().empty()) fail(source, "every scene must be a non-empty name");
    plan.scenes.push_back(s.get<std::string>());
  }
  if (!j.contains("comparisons") || !j.at("comparisons").is_array() || j.at("comparisons").empty()) {
    fail(source, "\"comparisons\" must be a non-empty list of {\"name\", \"reference\", \"test\"}");
  }
  std::set<std::string> names;
  for (std::size_t i = 0; i < j.at("comparisons").size(); ++i) {
    const json& c = j.at("comparisons")[i];
    const std::string where = "comparison " + std::to_string(i + 1);
    if (!c.is_object() || !c.contains("reference") || !c.contains("test")) {
      fail(source, where + " needs \"reference\" and \"test\"");
    }
    StudyComparison comparison;
    comparison.name = c.value("name", where);
    if (!names.insert(comparison.name).second) fail(source, "two comparisons are named \"" + comparison.name + "\"");
    comparison.reference = condition(c.at("reference"), comparison.name + " reference", source);
    comparison.test = condition(c.at("test"), comparison.name + " test", source);
    plan.comparisons.push_back(std::move(comparison));
  }
  plan.interval_s = number(j, "interval_s", plan.interval_s, 0.5, kMaxIntervalS, source);
  plan.blank_s = number(j, "blank_s", plan.blank_s, 0.0, kMaxIntervalS, source);
  const double repetitions = number(j, "repetitions", plan.repetitions, 1, kMaxRepetitions, source);
  if (repetitions != std::floor(repetitions)) fail(source, "\"repetitions\" must be a whole number");
  plan.repetitions = static_cast<int>(repetitions);
  if (j.contains("seed")) {
    if (!j.at("seed").is_number_unsigned()) fail(source, "\"seed\" must be a whole number >= 0");
    plan.seed = j.at("seed").get<std::uint64_t>();
  }
  return plan;
}

StudyPlan loadStudyPlan(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw StudyFileError(path + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return parseStudyPlan(text.str(), path);
}

}  // namespace viewer
