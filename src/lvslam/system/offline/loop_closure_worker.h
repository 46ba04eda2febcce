#pragma once
// Loop closure beside the run (docs/architecture.md, "Offline refinement"):
// the LiDAR thread hands each keyframe over and goes on; a thread of its own
// recognises places, verifies them and re-solves the global pose graph after
// each accepted loop, so the online output never waits for it. Deterministic
// runs keep the keyframes and process them at finish(), in the same order,
// to the same figures (the final graph is solved from the odometry poses
// either way).
#include <condition_variable>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>
#include <thread>

#include "lvslam/loop/loop_closure.h"

namespace lvslam::system {

class LoopClosureWorker {
 public:
  // `map`: a saved map's keyframes to localise the run in as well (--map-in), or none.
  LoopClosureWorker(const loop::LoopClosureConfig& config, const lidar::RegistrationConfig& registration,
                    bool threaded, std::shared_ptr<const std::vector<loop::LoopKeyframe>> map = nullptr);
  ~LoopClosureWorker();
  LoopClosureWorker(const LoopClosureWorker&) = delete;
  LoopClosureWorker& operator=(const LoopClosureWorker&) = delete;

  // Never waits for the loop closure's work (only for the queue's lock).
  void add(loop::LoopKeyframe keyframe);
  // Every keyframe processed, the graph solved; rethrows an error of the
  // worker's thread. Call once.
  loop::LoopClosureResult finish();
  // The run's keyframes (their odometry poses and features), moved out
  // after finish(): what a saved map is made of.
  std::vector<loop::LoopKeyframe> takeKeyframes();

  // The graph as last solved on the worker's thread (after an accepted
  // loop; empty before): what a live consumer of the map would read.
  std::vector<Eigen::Isometry3d> latestCorrectedPoses() const;
  int liveSolves() const;

 private:
  void run();
  void process(loop::LoopKeyframe keyframe);

  loop::LoopClosure closure_;
  std::optional<loop::MapLocalizer> localizer_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<loop::LoopKeyframe> queue_;
  bool closing_ = false;
  std::exception_ptr error_;
  std::vector<Eigen::Isometry3d> latest_;  // guarded by mutex_
  int live_solves_ = 0;                    // guarded by mutex_
  std::thread thread_;
};

}  // namespace lvslam::system
