#pragma once
// Publish latency of the odometry: for each camera frame, the wall time from
// the image's arrival at the node to its odometry's publication, and, when
// the ROS clock follows the data (a live robot, or `rosbag play --clock` with
// use_sim_time), from the image's stamp to the publication on that clock.
// Median and p95 of both at shutdown.
#include <chrono>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace lvslam::ros_node {

struct LatencySummary {
  std::size_t frames = 0;
  double arrival_median_ms = 0.0, arrival_p95_ms = 0.0;
  std::size_t stamp_frames = 0;  // frames whose clock-based figure counted
  double stamp_median_ms = 0.0, stamp_p95_ms = 0.0;
};

class PublishLatency {
 public:
  using Clock = std::chrono::steady_clock;

  void arrived(double stamp, Clock::time_point when);
  // `clock_now`: the ROS clock at publication; ignored when it is more than
  // a minute away from the stamp (a bag replayed without --clock).
  void published(double stamp, Clock::time_point when, double clock_now);
  LatencySummary summary() const;

 private:
  mutable std::mutex mutex_;
  std::map<double, Clock::time_point> arrivals_;  // frames not yet published
  std::vector<double> arrival_ms_, stamp_ms_;
};

std::string formatLatency(const LatencySummary& s);

}  // namespace lvslam::ros_node
