#include "lvslam/system/online/online_stage.h"

namespace lvslam::system {

OnlineStage::OnlineStage(std::unique_ptr<OnlineOutput> output, bool has_visual, bool has_lidar)
    : output_(std::move(output)), has_visual_(has_visual), has_lidar_(has_lidar) {}

void OnlineStage::frameArrived(std::size_t index, std::chrono::steady_clock::time_point when) {
  const std::lock_guard lock(mutex_);
  if (arrivals_.size() <= index) arrivals_.resize(index + 1);
  arrivals_[index] = when;
}

void OnlineStage::visualReady(std::size_t index, const VisualFrameRecord& record) {
  const std::lock_guard lock(mutex_);
  pending_[index].visual = record;
  pending_[index].visual->result.observations = {};  // replay data: not for the online output
  runReady();
}

void OnlineStage::lidarReady(std::size_t index, const LidarFrameRecord& record) {
  const std::lock_guard lock(mutex_);
  if (index < frames_.size()) {  // out already: a better pose for the estimator's window
    output_->lidarImproved(index, record);
    return;
  }
  pending_[index].lidar = record;
  pending_[index].lidar->fusion_lines.clear();
  runReady();
}

void OnlineStage::runReady() {
  while (true) {
    const auto next = pending_.find(frames_.size());
    if (next == pending_.end()) return;
    Pending& p = next->second;
    if ((has_visual_ && !p.visual) || (has_lidar_ && !p.lidar)) return;
    FrameOutput frame = output_->add(p.visual ? &*p.visual : nullptr, p.lidar ? &*p.lidar : nullptr);
    const std::size_t index = frames_.size();
    if (index < arrivals_.size())
      frame.latency_ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - arrivals_[index]).count();
    frames_.push_back(std::move(frame));
    pending_.erase(next);
    if (listener_) listener_(frames_.back());
  }
}

void OnlineStage::finish(const std::vector<VisualFrameRecord>& visual, const std::vector<LidarFrameRecord>& lidar) {
  const std::lock_guard lock(mutex_);
  const std::size_t count = has_visual_ ? visual.size() : lidar.size();
  for (std::size_t i = frames_.size(); i < count; ++i) {
    Pending& p = pending_[i];
    if (has_visual_ && !p.visual && i < visual.size()) p.visual = visual[i];
    if (has_lidar_ && !p.lidar && i < lidar.size()) p.lidar = lidar[i];
  }
  runReady();
}

std::vector<FrameOutput> OnlineStage::takeFrames() {
  const std::lock_guard lock(mutex_);
  return std::move(frames_);
}

}  // namespace lvslam::system
