#pragma once
// The constant-velocity model that predicts and deskews the next scan, as a
// Kalman filter (information form): the step between two registered poses
// measures the body velocity with twice the pose's covariance over dt^2,
// nothing along a direction the registration did not see; the platform's
// acceleration blurs the previous estimate over dt. A registration that
// slides along a direction it saw poorly moves the velocity only as far as
// the two uncertainties say, so one bad scan is not carried into the next.
#include "lvslam/core/se3.h"

namespace lvslam::lidar {

struct VelocityEstimate {
  Vector6d velocity = Vector6d::Zero();  // body twist per second (rho, phi)
  // 100 m/s and 100 rad/s (1 sigma) until a registration says more.
  Matrix6d covariance = Matrix6d::Identity() * 1e4;
};

// The platform's acceleration, 1 sigma (lidar.motion_accel, motion_angular_accel_deg).
struct VelocityNoise {
  double accel = 0.0;          // m/s^2
  double angular_accel = 0.0;  // rad/s^2
};

// `measured`: the body velocity between the previous and this registered
// pose, dt apart; `pose_information`: this pose's information (body-frame
// perturbation (rho, phi)), zero along the directions it did not see.
VelocityEstimate updateVelocity(const VelocityEstimate& previous, const Vector6d& measured,
                                const Matrix6d& pose_information, double dt, const VelocityNoise& noise);

}  // namespace lvslam::lidar
