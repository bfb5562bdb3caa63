// Runs a blind comparison study (study_plan.h) through the server's control socket: for each trial
// and interval it pauses the server, loads the scene, sets the condition's method and settings,
// restarts the scene so every interval runs the same segment from the same start, and resumes; the
// viewer shows the frames for the interval's length with every cue hidden, blanks the screen
// between, and asks the question. Results go to a CSV as each trial ends (study_results.h), the
// summary when the study ends or is stopped. No GL here: ViewerApp draws what screen() says.
#pragma once

#include <chrono>
#include <cstdint>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "decoded_frame.h"
#include "network_client.h"
#include "study_plan.h"
#include "study_results.h"
#include "study_trials.h"

namespace viewer {

// The study's CSV cannot be written (before anything is sent to the server).
class StudyOutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class StudyRunner {
 public:
  using Clock = std::chrono::steady_clock;
  // How long a control reply or the restarted segment's first frame may take before the study
  // stops with an error.
  static constexpr auto kServerWait = std::chrono::seconds(60);
  static constexpr auto kStatusRetry = std::chrono::milliseconds(200);

  enum class Screen { kBlank, kFrames, kQuestion, kDone };

  // `out_path` empty: "<study name>_<seed>.csv" in the working folder. Opens the CSV (throws
  // StudyOutputError when it cannot) and asks the server for its status.
  StudyRunner(StudyPlan plan, std::string out_path, NetworkClient& client);

  void onReply(const gsph::v1::ControlReply& reply, Clock::time_point now);
  // Once per rendered picture, with the newest frame and whether it arrived since the last call.
  void update(Clock::time_point now, const DecodedFrame* frame, bool new_frame);
  // A key: 1 or 2 (two-interval: the interval; same/different: 1 same, 2 different). Ignored but
  // while the question is up.
  void answer(int which, Clock::time_point now);
  // The participant stopped the study (Esc): the summary of the trials so far is written.
  void stop();

  Screen screen() const;
  // The text to centre on a question or message screen.
  std::string prompt() const;
  bool done() const { return phase_ == Phase::kDone || phase_ == Phase::kFailed; }
  bool failed() const { return phase_ == Phase::kFailed; }
  const std::string& error() const { return error_; }
  std::uint64_t seed() const { return seed_; }
  const std::string& csvPath() const { return csv_path_; }
  const std::string& summaryPath() const { return summary_path_; }

 private:
  enum class Phase { kCheck, kSetup, kWaitRestart, kWaitResume, kShowing, kBlank, kQuestion, kDone, kFailed };

  void checkServer(const gsph::v1::ServerStatus& status);
  void startInterval(Clock::time_point now);
  void finishSetup(Clock::time_point now);
  void send(gsph::v1::Control request);
  const StudyCondition& condition() const;
  void fail(const std::string& why);
  void finish();
  void recordFrame(const DecodedFrame& frame);

  StudyPlan plan_;
  NetworkClient& client_;
  std::uint64_t seed_ = 0;
  std::vector<StudyTrial> trials_;
  std::string csv_path_, summary_path_;
  std::ofstream csv_;
  std::vector<TrialRecord> records_;
  // Each parameter any condition sets, at the server's value before the study: a condition that
  // does not name one runs with that value, not the previous condition's.
  std::map<std::string, double> baseline_;

  Phase phase_ = Phase::kCheck;
  std::size_t trial_ = 0;
  int interval_ = 0;
  std::set<std::uint64_t> pending_;  // request ids awaiting their reply
  bool reset_sent_ = false;
  gsph::v1::ServerStatus server_;                     // the server's state after the latest request
  std::optional<Clock::time_point> status_retry_at_;  // the first status request failed: ask again
  std::int64_t restart_step_ = 0;                     // the step count the restart left, from its reply
  Clock::time_point phase_start_{};
  TrialRecord current_;
  double first_sim_ = 0.0, last_sim_ = 0.0;
  Clock::time_point first_arrival_{}, last_arrival_{};
  std::string error_;
};

}  // namespace viewer
