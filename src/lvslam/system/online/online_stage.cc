#include "lvslam/system/online/online_stage.h"

namespace lvslam::system {

OnlineStage::OnlineStage(std::unique_ptr<OnlineOutput> output, bool has_visual, bool has_lidar)
    : output_(std::move(output)), has_visual_(has_visual), has_lidar_(has_lidar) {}

void OnlineStage::frameArrived(std::size_t index, std::chrono::steady_clock::time_point when) {
  const std::lock_guard lock(mutex_);
  arrivals_[index] = when;
}

void OnlineStage::visualReady(std::size_t index, const VisualFrameRecord& record) {
  const std::lock_guard lock(mutex_);
  VisualFrameRecord& kept = visual_[index] = record;
  kept.result.replay.observations = {};  // replay data: not for the online output
  runReady();
}

void OnlineStage::lidarReady(std::size_t index, const LidarFrameRecord& record) {
  const std::lock_guard lock(mutex_);
  lidar_events_.push_back({index, false, record});
  lidar_events_.back().record.fusion_lines.clear();
  runReady();
}

void OnlineStage::emit(const VisualFrameRecord* visual, const LidarFrameRecord* lidar) {
  FrameOutput frame = output_->add(visual, lidar);
  const std::size_t index = frames_.size();
  if (const auto arrival = arrivals_.find(index); arrival != arrivals_.end()) {
    frame.latency_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - arrival->second).count();
    arrivals_.erase(arrival);
  }
  frames_.push_back(frame);
  visual_.erase(index);
  if (listener_) listener_(frame);
}

void OnlineStage::runReady() {
  while (true) {
    const std::size_t next = frames_.size();
    const auto visual = visual_.find(next);
    if (!has_lidar_) {
      if (visual == visual_.end()) return;
      emit(&visual->second, nullptr);
      continue;
    }
    if (lidar_events_.empty()) return;
    const LidarInputEvent& event = lidar_events_.front();
    if (event.index < next) {  // out already: a better pose for the estimator's window
      output_->lidarImproved(event.index, event.record);
    } else {
      if (event.index > next) return;  // a frame the LiDAR never posed: finish() completes it
      if (has_visual_ && visual == visual_.end()) return;  // later LiDAR records wait for this frame
      emit(has_visual_ ? &visual->second : nullptr, &event.record);
    }
    lidar_events_.pop_front();
  }
}

void OnlineStage::finish(const RecordFile<VisualFrameRecord>& visual, const RecordFile<LidarFrameRecord>& lidar) {
  const std::lock_guard lock(mutex_);
  const std::size_t count = has_visual_ ? visual.size() : lidar.size();
  for (std::size_t i = frames_.size(); i < count && i < visual.size(); ++i) visual_.try_emplace(i, visual[i]);
  runReady();
  // Every record is in: a frame whose LiDAR pose never came takes the worker's final one.
  while (frames_.size() < count) {
    const std::size_t next = frames_.size();
    const auto v = visual_.find(next);
    const bool has_lidar_record = next < lidar.size();
    if ((has_visual_ && v == visual_.end()) || (has_lidar_ && !has_lidar_record)) return;
    const std::optional<LidarFrameRecord> l = has_lidar_ ? lidar.get(next) : std::nullopt;
    emit(has_visual_ ? &v->second : nullptr, l ? &*l : nullptr);
    runReady();
  }
}

RecordFile<FrameOutput> OnlineStage::takeFrames() {
  const std::lock_guard lock(mutex_);
  return std::move(frames_);
}

std::optional<EstimatorGraph> OnlineStage::takeGraph() {
  const std::lock_guard lock(mutex_);
  return output_->takeGraph();
}

}  // namespace lvslam::system
