#include "publish_latency.h"

#include <cmath>

#include <fmt/format.h>

#include "lvslam/eval/line_accuracy.h"  // quantile, as the run summary computes its latency figures

namespace lvslam::ros_node {

void PublishLatency::arrived(double stamp, Clock::time_point when) {
  std::lock_guard lock(mutex_);
  arrivals_[stamp] = when;
  // Frames that never get a pose (before the first, or dropped) must not pile up.
  constexpr std::size_t kMaxPending = 1000;
  if (arrivals_.size() > kMaxPending) arrivals_.erase(arrivals_.begin());
}

void PublishLatency::published(double stamp, Clock::time_point when, double clock_now) {
  std::lock_guard lock(mutex_);
  const auto it = arrivals_.find(stamp);
  if (it != arrivals_.end()) {
    arrival_ms_.push_back(std::chrono::duration<double, std::milli>(when - it->second).count());
    arrivals_.erase(arrivals_.begin(), std::next(it));  // older frames were dropped or will not come
  }
  const double stamp_ms = (clock_now - stamp) * 1e3;
  if (std::abs(stamp_ms) < 60e3) stamp_ms_.push_back(stamp_ms);
}

LatencySummary PublishLatency::summary() const {
  std::lock_guard lock(mutex_);
  LatencySummary s;
  s.frames = arrival_ms_.size();
  s.arrival_median_ms = eval::quantile(arrival_ms_, 0.5);
  s.arrival_p95_ms = eval::quantile(arrival_ms_, 0.95);
  s.stamp_frames = stamp_ms_.size();
  s.stamp_median_ms = eval::quantile(stamp_ms_, 0.5);
  s.stamp_p95_ms = eval::quantile(stamp_ms_, 0.95);
  return s;
}

std::string formatLatency(const LatencySummary& s) {
  std::string text = fmt::format("publish latency over {} frames: arrival to odometry median {:.1f} ms, p95 {:.1f} ms",
                                 s.frames, s.arrival_median_ms, s.arrival_p95_ms);
  if (s.stamp_frames > 0)
    text += fmt::format("; stamp to odometry on the ROS clock median {:.1f} ms, p95 {:.1f} ms ({} frames)",
                        s.stamp_median_ms, s.stamp_p95_ms, s.stamp_frames);
  else
    text += "; stamp to odometry: the ROS clock does not follow the stamps (replay with --clock and use_sim_time)";
  return text;
}

}  // namespace lvslam::ros_node
