#pragma once
// Parameter-block layouts shared by the residuals and the optimisers (no Ceres
// here). A pose block holds T_camera_world as [t (3), q (4: x, y, z, w)];
// its tangent is the SE3 twist (rho, phi) of a left update
// T <- expSE3(delta) T. A line block holds the world line's Plücker vector
// (m, d) scaled to unit norm; its tangent is the orthonormal update.
#include <array>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace lvslam::visual {

constexpr int kPoseBlockSize = 7;
constexpr int kPoseTangentSize = 6;
constexpr int kLineBlockSize = 6;
constexpr int kLineTangentSize = 4;

struct PinholeIntrinsics {
  double fx = 1.0, fy = 1.0, cx = 0.0, cy = 0.0;
};

using PoseBlock = std::array<double, kPoseBlockSize>;

inline PoseBlock toPoseBlock(const Eigen::Isometry3d& T_camera_world) {
  const Eigen::Quaterniond q(T_camera_world.linear());
  const Eigen::Vector3d t = T_camera_world.translation();
  return {t.x(), t.y(), t.z(), q.x(), q.y(), q.z(), q.w()};
}

inline Eigen::Isometry3d fromPoseBlock(const double* block) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::Quaterniond(block[6], block[3], block[4], block[5]).normalized().toRotationMatrix();
  T.translation() = Eigen::Vector3d(block[0], block[1], block[2]);
  return T;
}

}  // namespace lvslam::visual
