#pragma once
// Distance travelled along the LiDAR odometry up to each camera time, for
// the output fusion's drift term (pose_fusion.h: the path since a visual
// pose's landmarks were mapped).
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace lvslam::system {

class OdometryPathLength {
 public:
  // The camera centre at time t; times must increase (others are ignored).
  void add(double t, const Eigen::Vector3d& centre);
  // The path length at the last time <= t; none before the first.
  std::optional<double> at(double t) const;
  // Path from time t to the last time added (from the first when t is earlier).
  double since(double t) const;

 private:
  std::vector<double> times_, lengths_;
  Eigen::Vector3d last_ = Eigen::Vector3d::Zero();
};

}  // namespace lvslam::system
