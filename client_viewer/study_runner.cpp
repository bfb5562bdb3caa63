#include "study_runner.h"

#include <cstdio>
#include <random>
#include <stdexcept>

namespace viewer {

namespace {

double seconds(StudyRunner::Clock::duration d) { return std::chrono::duration<double>(d).count(); }

std::string summaryPathFor(const std::string& csv) {
  const std::string suffix = ".csv";
  if (csv.size() > suffix.size() && csv.compare(csv.size() - suffix.size(), suffix.size(), suffix) == 0) {
    return csv.substr(0, csv.size() - suffix.size()) + ".summary.csv";
  }
  return csv + ".summary.csv";
}

}  // namespace

StudyRunner::StudyRunner(StudyPlan plan, std::string out_path, NetworkClient& client)
    : plan_(std::move(plan)), client_(client) {
  seed_ = plan_.seed ? *plan_.seed
                     : (static_cast<std::uint64_t>(std::random_device{}()) << 32) ^
                           static_cast<std::uint64_t>(Clock::now().time_since_epoch().count());
  trials_ = makeTrials(plan_, seed_);
  csv_path_ = out_path.empty() ? plan_.name + "_" + std::to_string(seed_) + ".csv" : out_path;
  summary_path_ = summaryPathFor(csv_path_);
  csv_.open(csv_path_);
  if (!csv_) throw StudyOutputError("cannot write the study's results to " + csv_path_);
  client_.setControlTimeout(std::chrono::duration_cast<std::chrono::milliseconds>(kServerWait));
  writeTrialHeader(csv_);
  csv_.flush();
  std::fprintf(stderr, "sph_viewer: study %s, %zu trials, seed %llu, results to %s\n", plan_.name.c_str(),
               trials_.size(), static_cast<unsigned long long>(seed_), csv_path_.c_str());
  gsph::v1::Control request;
  request.mutable_status();
  send(std::move(request));
  phase_start_ = Clock::now();
}

void StudyRunner::send(gsph::v1::Control request) { pending_.insert(client_.sendControl(std::move(request))); }

const StudyCondition& StudyRunner::condition() const {
  const StudyTrial& t = trials_[trial_];
  const StudyComparison& c = plan_.comparisons[t.comparison];
  return t.intervals[static_cast<std::size_t>(interval_)] == Shown::kReference ? c.reference : c.test;
}

void StudyRunner::fail(const std::string& why) {
  error_ = why;
  std::fprintf(stderr, "sph_viewer: study stopped: %s\n", why.c_str());
  finish();
  phase_ = Phase::kFailed;
}

void StudyRunner::checkServer(const gsph::v1::ServerStatus& status) {
  // Everything the plan names must exist before the first change to the server.
  std::set<std::string> scenes(status.scenes().begin(), status.scenes().end());
  for (const std::string& scene : plan_.scenes) {
    if (scenes.count(scene) == 0) return fail("the server has no scene \"" + scene + "\"");
  }
  for (const StudyComparison& c : plan_.comparisons) {
    for (const StudyCondition* k : {&c.reference, &c.test}) {
      for (const auto& [key, value] : k->parameters) {
        const auto it = status.parameters().find(key);
        if (it == status.parameters().end()) return fail("the server has no setting \"" + key + "\"");
        baseline_[key] = it->second;
      }
    }
  }
  if (!plan_.preset.empty()) {
    gsph::v1::Control request;
    request.mutable_set_preset()->set_preset(plan_.preset);
    send(std::move(request));
  }
  startInterval(Clock::now());
}

void StudyRunner::startInterval(Clock::time_point now) {
  if (interval_ == 0) {
    current_ = TrialRecord{};
    current_.number = static_cast<int>(trial_) + 1;
    current_.trial = trials_[trial_];
  }
  const StudyCondition& k = condition();
  const std::string& scene = plan_.scenes[trials_[trial_].scene];
  gsph::v1::Control pause;
  pause.mutable_pause();
  send(std::move(pause));
  // Every restart fills the water and lets it settle (seconds for a big scene): only what differs
  // from the server's state is sent, and the scene restarts once at most (finishSetup).
  if (server_.scene() != scene) {
    gsph::v1::Control load;
    load.mutable_load_scene()->set_scene(scene);
    send(std::move(load));
  }
  if (server_.method() != k.method) {
    gsph::v1::Control method;
    method.mutable_set_method()->set_method(k.method);
    send(std::move(method));
  }
  if (!baseline_.empty()) {
    gsph::v1::Control parameters;
    auto& values = *parameters.mutable_set_parameters()->mutable_values();
    for (const auto& [key, value] : baseline_) values[key] = value;
    for (const auto& [key, value] : k.parameters) values[key] = value;
    send(std::move(parameters));
  }
  reset_sent_ = false;
  phase_ = Phase::kSetup;
  phase_start_ = now;
}

void StudyRunner::finishSetup(Clock::time_point now) {
  // A load or a change of levels restarted the scene while paused (step and sim time 0): that is
  // the segment's start. Otherwise restart it, so every interval runs from the same start.
  const bool fresh = server_.step() == 0 && server_.sim_time() == 0.0;
  if (!fresh && !reset_sent_) {
    gsph::v1::Control reset;
    reset.mutable_reset();
    send(std::move(reset));
    reset_sent_ = true;
    return;
  }
  restart_step_ = server_.step();
  phase_ = Phase::kWaitRestart;
  phase_start_ = now;
}

void StudyRunner::onReply(const gsph::v1::ControlReply& reply, Clock::time_point now) {
  if (pending_.erase(reply.request_id()) == 0 || done()) return;
  if (!reply.ok() && phase_ == Phase::kCheck) {
    // Not connected yet (the server may still be starting): ask again shortly, until kServerWait.
    status_retry_at_ = now + kStatusRetry;
    return;
  }
  if (!reply.ok()) return fail("the server refused a request: " + reply.error());
  server_ = reply.status();  // each reply's status is the state after its request
  if (phase_ == Phase::kCheck) {
    phase_start_ = now;
    return checkServer(reply.status());
  }
  if (phase_ == Phase::kSetup && pending_.empty()) finishSetup(now);
}

void StudyRunner::recordFrame(const DecodedFrame& frame) {
  IntervalRecord& r = current_.intervals[static_cast<std::size_t>(interval_)];
  if (r.frames == 0) {
    first_sim_ = frame.sim_time;
    first_arrival_ = frame.arrival;
  }
  last_sim_ = frame.sim_time;
  last_arrival_ = frame.arrival;
  ++r.frames;
  if (frame.gaze.mode == gsph::v1::GAZE_MODE_TRACKING) {
    ++r.gaze_tracking_frames;
    r.gaze_x_sum += frame.gaze.x;
    r.gaze_y_sum += frame.gaze.y;
    r.gaze_xx_sum += static_cast<double>(frame.gaze.x) * frame.gaze.x;
    r.gaze_yy_sum += static_cast<double>(frame.gaze.y) * frame.gaze.y;
  }
  const double wall = seconds(last_arrival_ - first_arrival_);
  r.realtime_ratio = wall > 0.0 ? (last_sim_ - first_sim_) / wall : 0.0;
}

void StudyRunner::update(Clock::time_point now, const DecodedFrame* frame, bool new_frame) {
  if (done()) return;
  const bool waiting = phase_ == Phase::kCheck || phase_ == Phase::kSetup || phase_ == Phase::kWaitRestart ||
                       phase_ == Phase::kWaitResume;
  if (waiting && now - phase_start_ > kServerWait) return fail("no answer or no restarted frame from the server");
  if (phase_ == Phase::kCheck && status_retry_at_ && now >= *status_retry_at_) {
    status_retry_at_.reset();
    gsph::v1::Control request;
    request.mutable_status();
    send(std::move(request));
  }
  const std::string& scene = plan_.scenes[trials_.empty() ? 0 : trials_[trial_].scene];
  switch (phase_) {
    case Phase::kWaitRestart:
      // Frames arrive in order: a paused frame at the restarted step of the right scene and method
      // comes after the restart, so every running frame after it belongs to this interval's segment.
      if (new_frame && frame != nullptr && frame->paused && frame->step == restart_step_ && frame->scene == scene &&
          frame->method == condition().method) {
        gsph::v1::Control resume;
        resume.mutable_resume();
        send(std::move(resume));
        phase_ = Phase::kWaitResume;
        phase_start_ = now;
      }
      break;
    case Phase::kWaitResume:
      if (new_frame && frame != nullptr && !frame->paused) {
        phase_ = Phase::kShowing;
        phase_start_ = now;
        recordFrame(*frame);
      }
      break;
    case Phase::kShowing:
      if (new_frame && frame != nullptr && !frame->paused) recordFrame(*frame);
      if (seconds(now - phase_start_) >= plan_.interval_s) {
        gsph::v1::Control pause;
        pause.mutable_pause();
        send(std::move(pause));
        phase_ = Phase::kBlank;
        phase_start_ = now;
      }
      break;
    case Phase::kBlank:
      if (seconds(now - phase_start_) < plan_.blank_s) break;
      if (interval_ == 0) {
        interval_ = 1;
        startInterval(now);
      } else {
        phase_ = Phase::kQuestion;
        phase_start_ = now;
        // For the operator's log and scripted runs; the screen shows the question only.
        std::fprintf(stderr, "sph_viewer: trial %zu of %zu: waiting for the answer\n", trial_ + 1, trials_.size());
      }
      break;
    default:
      break;
  }
}

void StudyRunner::answer(int which, Clock::time_point now) {
  if (phase_ != Phase::kQuestion || (which != 1 && which != 2)) return;
  current_.answer = which;
  current_.correct = answerCorrect(plan_.question, current_.trial, which);
  current_.response_s = seconds(now - phase_start_);
  records_.push_back(current_);
  writeTrialRow(csv_, plan_, seed_, current_);
  csv_.flush();
  interval_ = 0;
  if (++trial_ >= trials_.size()) {
    finish();
    phase_ = Phase::kDone;
    return;
  }
  startInterval(now);
}

void StudyRunner::stop() {
  if (done()) return;
  std::fprintf(stderr, "sph_viewer: study stopped after %zu of %zu trials\n", records_.size(), trials_.size());
  finish();
  phase_ = Phase::kDone;
}

void StudyRunner::finish() {
  std::ofstream summary(summary_path_);
  writeSummary(summary, plan_, seed_, records_);
  if (!summary) std::fprintf(stderr, "sph_viewer: cannot write %s\n", summary_path_.c_str());
  std::fprintf(stderr, "sph_viewer: study results in %s, summary in %s\n", csv_path_.c_str(), summary_path_.c_str());
}

StudyRunner::Screen StudyRunner::screen() const {
  switch (phase_) {
    case Phase::kShowing:
      return Screen::kFrames;
    case Phase::kQuestion:
      return Screen::kQuestion;
    case Phase::kDone:
    case Phase::kFailed:
      return Screen::kDone;
    default:
      return Screen::kBlank;
  }
}

std::string StudyRunner::prompt() const {
  if (phase_ == Phase::kQuestion) {
    return plan_.question == StudyQuestion::kTwoInterval
               ? "Which of the two looked more detailed?   1: the first   2: the second"
               : "Did the two look the same?   S: same   D: different";
  }
  if (phase_ == Phase::kFailed) return "The study stopped: " + error_;
  if (phase_ == Phase::kDone) return "Thank you: the study is complete.";
  return {};
}

}  // namespace viewer
