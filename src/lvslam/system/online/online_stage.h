#pragma once
// Joins the two subsystems' records of each camera frame as they become
// ready (from either worker's thread) and runs the online output in frame
// order as soon as a frame is complete, so a pose is out as soon as the
// data fix it: the visual record after tracking, the LiDAR's when the sweep
// after the frame is registered. Records each frame's latency (output wall
// time minus the frame's arrival). Thread-safe; what the output computes
// never depends on thread timing: the LiDAR's records (first poses and
// improvements) reach it in the order the LiDAR thread made them, and a
// frame whose visual record is late holds the LiDAR's later records back,
// exactly as when both run on one thread.
#include <chrono>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "lvslam/system/online/online_output.h"
#include "lvslam/system/record_fields.h"
#include "lvslam/system/record_file.h"

namespace lvslam::system {

class OnlineStage {
 public:
  OnlineStage(std::unique_ptr<OnlineOutput> output, bool has_visual, bool has_lidar);

  // The reading thread: frame `index` arrived at `when`.
  void frameArrived(std::size_t index, std::chrono::steady_clock::time_point when);
  void visualReady(std::size_t index, const VisualFrameRecord& record);
  // The frame's LiDAR pose; called again with a better one (interpolated
  // between two sweeps), which goes to the output as an improvement when
  // the frame is out already.
  void lidarReady(std::size_t index, const LidarFrameRecord& record);
  // After the run: frames a half never came for (a LiDAR pose that never
  // became known) are completed with the workers' final records.
  void finish(const RecordFile<VisualFrameRecord>& visual, const RecordFile<LidarFrameRecord>& lidar);

  RecordFile<FrameOutput> takeFrames();
  // The fused estimator's graph over the whole run (OnlineOutput::takeGraph).
  std::optional<EstimatorGraph> takeGraph();
  // Called with each frame's output as it is made, in frame order (from
  // whichever thread completed the frame, under the stage's lock).
  void onFrameOutput(std::function<void(const FrameOutput&)> listener) { listener_ = std::move(listener); }
  const OnlineOutput& output() const { return *output_; }

 private:
  void runReady();  // with the lock held
  void emit(const VisualFrameRecord* visual, const LidarFrameRecord* lidar);

  std::unique_ptr<OnlineOutput> output_;
  bool has_visual_, has_lidar_;
  std::mutex mutex_;
  std::map<std::size_t, VisualFrameRecord> visual_;  // ready, not yet out
  std::deque<LidarInputEvent> lidar_events_;        // in the LiDAR thread's order
  std::map<std::size_t, std::chrono::steady_clock::time_point> arrivals_;  // of the frames not yet out
  RecordFile<FrameOutput> frames_;
  std::function<void(const FrameOutput&)> listener_;
};

}  // namespace lvslam::system
