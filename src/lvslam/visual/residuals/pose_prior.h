#pragma once
// Prior on a keyframe pose from the LiDAR odometry (lvslam's addition to the
// paper's BA, docs/visual-subsystem.md): the camera pose the LiDAR subsystem
// gives at the keyframe's time, moved into the visual map. Residual on
// T = T_camera_world against the prior T_p:
//   e = [ (c - c_p) / sigma_t ; log(R R_p^T) / sigma_r ],  c = -R^T t,
// the camera centre in the world and the rotation error in the camera frame,
// with analytic Jacobians for the left update T <- exp(delta) T:
//   dc/drho = -R^T, dc/dphi = 0, dlog/dphi = J_l^-1(log(R R_p^T)).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "lvslam/core/se3.h"
#include "lvslam/visual/residuals/pose_block.h"

namespace lvslam::visual {

struct PosePrior {
  static void evaluate(const Eigen::Isometry3d& T_camera_world, const Eigen::Isometry3d& prior_T_camera_world,
                       double inv_sigma_t, double inv_sigma_r, Eigen::Matrix<double, 6, 1>& residual,
                       Eigen::Matrix<double, 6, 6>* J_pose) {
    const Eigen::Matrix3d R = T_camera_world.linear();
    const Eigen::Vector3d c = -R.transpose() * T_camera_world.translation();
    const Eigen::Matrix3d R_p = prior_T_camera_world.linear();
    const Eigen::Vector3d c_p = -R_p.transpose() * prior_T_camera_world.translation();
    const Eigen::Vector3d r_rot = logSO3(R * R_p.transpose());
    residual.head<3>() = inv_sigma_t * (c - c_p);
    residual.tail<3>() = inv_sigma_r * r_rot;
    if (J_pose) {
      J_pose->setZero();
      J_pose->topLeftCorner<3, 3>() = -inv_sigma_t * R.transpose();
      J_pose->bottomRightCorner<3, 3>() = inv_sigma_r * leftJacobianSO3Inverse(r_rot);
    }
  }
};

}  // namespace lvslam::visual
