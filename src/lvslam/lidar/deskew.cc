#include "lvslam/lidar/deskew.h"

namespace lvslam::lidar {

Eigen::Isometry3d motionOver(const Vector6d& velocity, double dt) { return expSE3(velocity * dt); }

void deskewToReference(std::vector<TimedPoint>& points, const Vector6d& velocity) {
  if (velocity.isZero(0.0)) return;
  for (TimedPoint& point : points) {
    const Eigen::Isometry3d T_ref_at = motionOver(velocity, point.time);
    point.p = (T_ref_at * point.p.cast<double>()).cast<float>();
  }
}

Vector6d velocityBetween(const Eigen::Isometry3d& T_world_prev, double t_prev, const Eigen::Isometry3d& T_world_cur,
                         double t_cur) {
  const double dt = t_cur - t_prev;
  if (!(dt > 0.0)) return Vector6d::Zero();
  return logSE3(T_world_prev.inverse() * T_world_cur) / dt;
}

}  // namespace lvslam::lidar
