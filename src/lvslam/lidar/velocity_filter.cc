#include "lvslam/lidar/velocity_filter.h"

#include <Eigen/Cholesky>

namespace lvslam::lidar {

VelocityEstimate updateVelocity(const VelocityEstimate& previous, const Vector6d& measured,
                                const Matrix6d& pose_information, double dt, const VelocityNoise& noise) {
  if (!(dt > 0.0)) return previous;
  const double a = noise.accel * dt, w = noise.angular_accel * dt;
  Vector6d process;
  process << a * a, a * a, a * a, w * w, w * w, w * w;
  const Matrix6d predicted = (previous.covariance + Matrix6d(process.asDiagonal())).inverse();
  // Velocity = (pose - previous pose) / dt: two poses' covariance over dt^2.
  const Matrix6d measurement = pose_information * (dt * dt / 2.0);
  const Eigen::LDLT<Matrix6d> total(predicted + measurement);
  VelocityEstimate next;
  next.covariance = total.solve(Matrix6d::Identity());
  next.velocity = total.solve(predicted * previous.velocity + measurement * measured);
  return next;
}

}  // namespace lvslam::lidar
