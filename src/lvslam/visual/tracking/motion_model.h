#pragma once
// ORB-SLAM's constant-velocity motion model, in time rather than in frames:
// a recording that drops frames or jumps in time moves the camera by as many
// steps of the last motion as frame intervals have passed.
#include <Eigen/Geometry>

namespace lvslam::visual {

struct ConstantVelocity {
  Eigen::Isometry3d velocity = Eigen::Isometry3d::Identity();  // T_now * T_before^-1 (camera from world)
  double dt = 0.0;  // seconds the velocity spans; <= 0: unknown, one step per call
};

// T_camera_world predicted `elapsed` seconds after T_last. When elapsed is a
// whole number n >= 1 of intervals (within a quarter), the velocity is
// applied n times (so regular frames give exactly velocity * T_last); else
// its logarithm is scaled (a fraction of a step, or a long gap).
Eigen::Isometry3d predictPose(const ConstantVelocity& model, const Eigen::Isometry3d& T_last, double elapsed);

}  // namespace lvslam::visual
