#include "lvslam/system/offline/loop_closure_worker.h"

namespace lvslam::system {

LoopClosureWorker::LoopClosureWorker(const loop::LoopClosureConfig& config,
                                     const lidar::RegistrationConfig& registration, bool threaded,
                                     std::shared_ptr<const std::vector<loop::LoopKeyframe>> map)
    : closure_(config, registration) {
  if (map) localizer_.emplace(std::move(map), config, registration);
  if (threaded) thread_ = std::thread([this] { run(); });
}

LoopClosureWorker::~LoopClosureWorker() {
  {
    const std::lock_guard lock(mutex_);
    closing_ = true;
    queue_.clear();  // nobody will read the result
  }
  wake_.notify_one();
  if (thread_.joinable()) thread_.join();
}

void LoopClosureWorker::add(loop::LoopKeyframe keyframe) {
  {
    const std::lock_guard lock(mutex_);
    queue_.push_back(std::move(keyframe));
  }
  wake_.notify_one();
}

// The live graph after an accepted loop: what a live system would show; the
// result of the run is the final solve of finish().
void LoopClosureWorker::process(loop::LoopKeyframe keyframe) {
  if (localizer_) localizer_->addKeyframe(keyframe);
  if (!closure_.addKeyframe(std::move(keyframe)) || !thread_.joinable()) return;
  loop::LoopClosureResult live = closure_.solve();
  const std::lock_guard lock(mutex_);
  latest_ = std::move(live.T_odom_lidar_corrected);
  ++live_solves_;
}

std::vector<Eigen::Isometry3d> LoopClosureWorker::latestCorrectedPoses() const {
  const std::lock_guard lock(mutex_);
  return latest_;
}

int LoopClosureWorker::liveSolves() const {
  const std::lock_guard lock(mutex_);
  return live_solves_;
}

void LoopClosureWorker::run() {
  while (true) {
    std::unique_lock lock(mutex_);
    wake_.wait(lock, [this] { return closing_ || !queue_.empty(); });
    if (queue_.empty()) return;  // closing and drained
    loop::LoopKeyframe keyframe = std::move(queue_.front());
    queue_.pop_front();
    lock.unlock();
    try {
      process(std::move(keyframe));
    } catch (...) {
      const std::lock_guard relock(mutex_);
      error_ = std::current_exception();
      queue_.clear();
      return;
    }
  }
}

loop::LoopClosureResult LoopClosureWorker::finish() {
  if (thread_.joinable()) {
    {
      const std::lock_guard lock(mutex_);
      closing_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }
  if (error_) std::rethrow_exception(error_);
  while (!queue_.empty()) {
    process(std::move(queue_.front()));
    queue_.pop_front();
  }
  loop::LoopClosureResult result = closure_.solve();
  if (localizer_) result.map_localization = localizer_->result();
  return result;
}

std::vector<loop::LoopKeyframe> LoopClosureWorker::takeKeyframes() { return closure_.takeKeyframes(); }

}  // namespace lvslam::system
