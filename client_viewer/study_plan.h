// A blind comparison study as its file describes it (scenes/studies/*.json; client_viewer/README.md,
// "User studies"): the scenes, the comparisons (a reference and a test condition, each a method with
// optional settings), the interval and blank lengths, the repetitions and the question. Parsing
// checks everything it can without a server and names the first problem, so a bad file changes
// nothing.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "proto/sph.pb.h"

namespace viewer {

class StudyFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Two-interval forced choice: "which of the two looked more detailed?" (1 or 2; correct: the
// reference's interval). Same/different: "did the two look the same?" (S or D; correct: whether
// the two intervals showed one condition).
enum class StudyQuestion { kTwoInterval, kSameDifferent };

struct StudyCondition {
  gsph::v1::Method method = gsph::v1::METHOD_UNSPECIFIED;
  std::map<std::string, double> parameters;  // SetParametersRequest values, sent after the method
  std::string label() const;                 // "foveated foveated_quality=1.5", for the output only
};

struct StudyComparison {
  std::string name;
  StudyCondition reference;  // the full-detail one (usually regular)
  StudyCondition test;
};

struct StudyPlan {
  std::string name;
  StudyQuestion question = StudyQuestion::kTwoInterval;
  std::string preset;  // empty: each scene's own
  std::vector<std::string> scenes;
  std::vector<StudyComparison> comparisons;
  double interval_s = 4.0;            // each interval's wall-clock length
  double blank_s = 1.0;               // blank screen before and between the intervals
  int repetitions = 1;                // trials per scene and comparison
  std::optional<std::uint64_t> seed;  // none: from the clock (written to the output either way)
};

// Throws StudyFileError naming the file and the first problem.
StudyPlan parseStudyPlan(const std::string& json_text, const std::string& source_name);
StudyPlan loadStudyPlan(const std::string& path);

const char* questionName(StudyQuestion question);
// The method's name as the server's command line spells it; nullptr for one it does not name.
const char* studyMethodName(gsph::v1::Method method);

}  // namespace viewer
