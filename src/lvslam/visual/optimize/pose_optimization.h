#pragma once
// Motion-only pose optimisation of the tracker: the camera pose against fixed
// map points and lines, with ORB-SLAM's outlier rejection (rounds of
// robust Gauss-Newton, each followed by a chi2 test on every observation,
// the last round without the robust kernel). A hand-written 6-DoF
// Levenberg-Marquardt on the same residual functions the BA uses: per frame
// this runs hundreds of times, so no Ceres set-up cost and no allocation in
// the inner loop.
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "lvslam/core/plucker_line.h"
#include "lvslam/core/se3.h"
#include "lvslam/visual/residuals/pose_block.h"

namespace lvslam::visual {

struct PoseOptimizationConfig {
  int rounds = 4;                    // ORB-SLAM: 4 rounds ...
  int iterations_per_round = 10;     // ... of 10 iterations
  double chi2_point = 5.991;         // 95 % chi2, 2 DoF
  double chi2_line = 5.991;
  double huber_delta = 2.447651936;  // sqrt(5.991)
  int min_inliers = 10;              // fewer: the pose is reported as failed
};

struct PosePointObservation {
  Eigen::Vector3d p_world = Eigen::Vector3d::Zero();
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();  // undistorted
  double inv_sigma2 = 1.0;
};

struct PoseLineObservation {
  PluckerLine line_world;
  Eigen::Vector2d start = Eigen::Vector2d::Zero(), end = Eigen::Vector2d::Zero();
  double inv_sigma2 = 1.0;
};

struct PoseOptimizationResult {
  bool success = false;  // enough inliers and a finite pose
  Eigen::Isometry3d T_camera_world = Eigen::Isometry3d::Identity();
  std::vector<bool> point_inlier, line_inlier;
  int num_inliers = 0;
  // J^T J of the whitened inlier residuals at the final pose, for the left
  // update T <- exp(delta) T (delta = (rho, phi), the camera frame's): the
  // pose's information when the observations' sigmas are right.
  Matrix6d information = Matrix6d::Zero();
};

PoseOptimizationResult optimizePose(const Eigen::Isometry3d& T_camera_world_initial,
                                    const std::vector<PosePointObservation>& points,
                                    const std::vector<PoseLineObservation>& lines,
                                    const PinholeIntrinsics& intrinsics,
                                    const PoseOptimizationConfig& config = {});

}  // namespace lvslam::visual
