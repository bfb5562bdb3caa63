#include "net/input_mailbox.h"

#include <algorithm>

namespace net {

void InputMailbox::putGaze(const GazeArrival& gaze) {
  {
    std::lock_guard lock(mutex_);
    gaze_ = gaze;
    has_gaze_ = true;
    woken_ = true;
  }
  // An idle simulation thread may step early for a new sample (SimLoop::run).
  wake_cv_.notify_one();
}

bool InputMailbox::latestGaze(GazeArrival& out) const {
  std::lock_guard lock(mutex_);
  if (has_gaze_) out = gaze_;
  return has_gaze_;
}

void InputMailbox::putPose(const PoseArrival& pose) {
  std::lock_guard lock(mutex_);
  if (poses_.size() >= kMaxViewers && poses_.count(pose.viewer_id) == 0) {
    // Forget the viewer that has been quiet longest so a churn of viewer ids cannot grow the map.
    auto oldest = std::min_element(poses_.begin(), poses_.end(),
                                   [](const auto& a, const auto& b) { return a.second.arrived < b.second.arrived; });
    poses_.erase(oldest);
  }
  poses_[pose.viewer_id] = pose;
  newest_viewer_ = pose.viewer_id;
  ++pose_version_;
}

bool InputMailbox::selectedPose(const std::string& viewer_id, PoseArrival& out) const {
  std::lock_guard lock(mutex_);
  const auto it = poses_.find(viewer_id.empty() ? newest_viewer_ : viewer_id);
  if (it == poses_.end()) return false;
  out = it->second;
  return true;
}

std::uint64_t InputMailbox::poseVersion() const {
  std::lock_guard lock(mutex_);
  return pose_version_;
}

std::size_t InputMailbox::viewerCount() const {
  std::lock_guard lock(mutex_);
  return poses_.size();
}

bool InputMailbox::pushControl(ControlRequest&& request) {
  {
    std::lock_guard lock(mutex_);
    if (controls_.size() >= kMaxQueuedControls) return false;
    controls_.push_back(std::move(request));
    woken_ = true;
  }
  wake_cv_.notify_one();
  return true;
}

void InputMailbox::takeControls(std::vector<ControlRequest>& out) {
  std::lock_guard lock(mutex_);
  while (!controls_.empty()) {
    out.push_back(std::move(controls_.front()));
    controls_.pop_front();
  }
}

void InputMailbox::waitUntil(SteadyTime deadline) {
  std::unique_lock lock(mutex_);
  wake_cv_.wait_until(lock, deadline, [this] { return woken_; });
  woken_ = false;
}

void InputMailbox::wake() {
  {
    std::lock_guard lock(mutex_);
    woken_ = true;
  }
  wake_cv_.notify_one();
}

}  // namespace net
