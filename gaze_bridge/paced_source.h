// Sources that make their samples themselves (replay, synthetic) and release each at its time on the
// bridge clock: sample time t (seconds from the first) is due at start + t / speed.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "gaze/fixation_model.h"
#include "gaze/gaze_recording.h"
#include "gaze_source.h"

namespace gaze_bridge {

class PacedSource : public GazeSource {
 public:
  void poll(std::vector<TrackerSample>& out, int timeout_ms) override;
  bool connected() const override { return true; }
  bool finished() const override { return exhausted_; }

 protected:
  explicit PacedSource(double speed);
  // The next point, time_s increasing (tracker clock); false when there are no more.
  virtual bool nextPoint(gaze::GazePoint& point) = 0;

 private:
  bool fetch();
  double speed_;
  bool started_ = false;
  bool exhausted_ = false;
  bool have_pending_ = false;
  gaze::GazePoint pending_;
  double origin_time_s_ = 0.0;  // time_s of the first point
  std::int64_t start_ns_ = 0;   // bridge clock when the first point was due
};

// The fixation/saccade model in real time (the default source).
class SyntheticSource : public PacedSource {
 public:
  explicit SyntheticSource(const gaze::FixationModelParams& params);
  std::string id() const override { return "synthetic"; }

 protected:
  bool nextPoint(gaze::GazePoint& point) override;

 private:
  gaze::FixationSaccadeModel model_;
};

// A recording at its own pace times `speed`, looped (the loop period is the recording's duration plus
// one mean sample interval, and tracker time keeps increasing across loops).
class ReplaySource : public PacedSource {
 public:
  // Throws gaze::GazeFormatError for a bad recording, std::invalid_argument for speed <= 0.
  ReplaySource(const std::string& path, double speed, bool loop);
  ReplaySource(gaze::GazeRecording recording, double speed, bool loop);
  std::string id() const override { return "replay"; }

 protected:
  bool nextPoint(gaze::GazePoint& point) override;

 private:
  gaze::GazeRecording recording_;
  bool loop_;
  double period_s_;
  std::size_t index_ = 0;
  std::uint64_t loops_ = 0;
};

}  // namespace gaze_bridge
