#pragma once
// LiDAR depth residual of a point seen by a keyframe with a measured depth
// z_lidar for that keypoint (DEMO, Zhang et al. 2014 / LIMO, Graeter et al.
// 2018; ORB-SLAM2's RGB-D depth term): e = (z_c(T_cw p_w) - z_lidar) / sigma,
// with analytic Jacobians for the left SE3 pose update and the world point.
// It ties the monocular map to the metric LiDAR scale.
#include <ceres/sized_cost_function.h>

#include <Eigen/Core>

#include "lvslam/core/se3.h"
#include "lvslam/visual/residuals/pose_block.h"

namespace lvslam::visual {

struct PointDepth {
  // False when the point is not in front of the camera or input is not finite.
  static bool evaluate(const Eigen::Matrix3d& R_cw, const Eigen::Vector3d& t_cw, const Eigen::Vector3d& p_w,
                       double depth, double inv_sigma, double& residual, Eigen::Matrix<double, 1, 6>* J_pose,
                       Eigen::Matrix<double, 1, 3>* J_point) {
    const Eigen::Vector3d p_c = R_cw * p_w + t_cw;
    if (!(p_c.z() > 1e-6) || !p_c.allFinite()) return false;
    residual = inv_sigma * (p_c.z() - depth);
    if (J_pose) {
      // e_z^T d p_c / d(rho, phi) = e_z^T [I, -[p_c]x] for T <- exp(delta) T.
      *J_pose << 0.0, 0.0, inv_sigma, inv_sigma * p_c.y(), -inv_sigma * p_c.x(), 0.0;
    }
    if (J_point) *J_point = inv_sigma * R_cw.row(2);
    return true;
  }
};

// Blocks: pose [t, q] (Se3LeftManifold convention), point p_w (3). Two rows,
// the second always 0: with every point row 2 high, Ceres' Schur elimination
// uses its fixed-size <2, 3, 6> kernels instead of the dynamic ones.
class PointDepthCost final : public ceres::SizedCostFunction<2, kPoseBlockSize, 3> {
 public:
  PointDepthCost(double depth, double inv_sigma) : depth_(depth), inv_sigma_(inv_sigma) {}

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const Eigen::Isometry3d T = fromPoseBlock(parameters[0]);
    const Eigen::Vector3d p_w = Eigen::Map<const Eigen::Vector3d>(parameters[1]);
    Eigen::Matrix<double, 1, 6> J_pose;
    Eigen::Matrix<double, 1, 3> J_point;
    const bool want_pose = jacobians && jacobians[0];
    const bool want_point = jacobians && jacobians[1];
    if (!PointDepth::evaluate(T.linear(), T.translation(), p_w, depth_, inv_sigma_, residuals[0],
                              want_pose ? &J_pose : nullptr, want_point ? &J_point : nullptr)) {
      return false;
    }
    residuals[1] = 0.0;
    if (want_pose) {
      Eigen::Matrix<double, 2, 6> J = Eigen::Matrix<double, 2, 6>::Zero();
      J.row(0) = J_pose;
      writePoseJacobian(J, jacobians[0]);
    }
    if (want_point) {
      Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>> J{jacobians[1]};
      J.row(0) = J_point;
      J.row(1).setZero();
    }
    return true;
  }

 private:
  double depth_, inv_sigma_;
};

}  // namespace lvslam::visual
