#include "paced_source.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

namespace gaze_bridge {

namespace {

// A bridge that stalled (suspended laptop, debugger) must not flood the server with the backlog:
// beyond this lag the schedule restarts from now.
constexpr std::int64_t kMaxLagNs = 500'000'000;

double checkedSpeed(double speed) {
  if (!(std::isfinite(speed) && speed > 0.0)) throw std::invalid_argument("replay speed must be > 0");
  return speed;
}

}  // namespace

PacedSource::PacedSource(double speed) : speed_(checkedSpeed(speed)) {}

bool PacedSource::fetch() {
  if (!have_pending_ && !exhausted_) {
    have_pending_ = nextPoint(pending_);
    exhausted_ = !have_pending_;
  }
  return have_pending_;
}

void PacedSource::poll(std::vector<TrackerSample>& out, int timeout_ms) {
  const std::int64_t deadline = steadyNowNs() + std::int64_t{std::max(timeout_ms, 0)} * 1'000'000;
  const std::size_t had = out.size();
  while (fetch()) {
    std::int64_t now = steadyNowNs();
    if (!started_) {
      started_ = true;
      origin_time_s_ = pending_.time_s;
      start_ns_ = now;
    }
    auto due = start_ns_ + static_cast<std::int64_t>((pending_.time_s - origin_time_s_) / speed_ * 1e9);
    if (now - due > kMaxLagNs) {  // resynchronise: the pending point is due now
      origin_time_s_ = pending_.time_s;
      start_ns_ = now;
      due = now;
    }
    if (due > now) {
      if (out.size() > had || due > deadline) {
        // Hand over what is due; otherwise sleep out the timeout.
        if (out.size() == had)
          std::this_thread::sleep_for(std::chrono::nanoseconds(std::max<std::int64_t>(deadline - now, 0)));
        return;
      }
      std::this_thread::sleep_for(std::chrono::nanoseconds(due - now));
      now = steadyNowNs();
    }
    TrackerSample sample;
    sample.tracker_time_s = pending_.time_s;
    sample.x = pending_.x;
    sample.y = pending_.y;
    sample.valid = pending_.valid;
    sample.confidence = pending_.valid ? 1.0f : 0.0f;
    sample.arrival_ns = now;
    out.push_back(sample);
    have_pending_ = false;
  }
  // Exhausted: nothing will come; do not spin the caller's loop.
  if (out.size() == had) {
    const std::int64_t now = steadyNowNs();
    if (deadline > now) std::this_thread::sleep_for(std::chrono::nanoseconds(deadline - now));
  }
}

SyntheticSource::SyntheticSource(const gaze::FixationModelParams& params) : PacedSource(1.0), model_(params) {}

bool SyntheticSource::nextPoint(gaze::GazePoint& point) {
  point = model_.next();
  return true;
}

ReplaySource::ReplaySource(const std::string& path, double speed, bool loop)
    : ReplaySource(gaze::readGazeRecording(path), speed, loop) {}

ReplaySource::ReplaySource(gaze::GazeRecording recording, double speed, bool loop)
    : PacedSource(speed), recording_(std::move(recording)), loop_(loop) {
  if (recording_.samples.empty()) throw std::invalid_argument("replay: the recording has no samples");
  const std::size_t n = recording_.samples.size();
  // One mean interval between the last sample and the first of the next loop; a one-sample recording
  // repeats every 1/120 s.
  period_s_ = n > 1 ? recording_.duration() * static_cast<double>(n) / static_cast<double>(n - 1) : 1.0 / 120.0;
}

bool ReplaySource::nextPoint(gaze::GazePoint& point) {
  if (index_ == recording_.samples.size()) {
    if (!loop_) return false;
    index_ = 0;
    ++loops_;
  }
  point = recording_.samples[index_++];
  point.time_s += static_cast<double>(loops_) * period_s_;
  return true;
}

}  // namespace gaze_bridge
