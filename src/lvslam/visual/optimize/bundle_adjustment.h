#pragma once
// Local bundle adjustment over keyframe poses, point landmarks and Plücker
// line landmarks (Structure PLP-SLAM's point-line BA with the line
// direction term of Cao et al., Sec. III-D). Plain data in and out: the map
// copies its local window in, runs this, and copies the result back.
// Solved by Levenberg-Marquardt on the Schur complement (schur_system.h).
#include <limits>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "lvslam/core/plucker_line.h"
#include "lvslam/visual/residuals/pose_block.h"

namespace lvslam::visual {

struct BundleAdjustmentConfig {
  int first_stage_iterations = 5;    // with every observation, robust
  int second_stage_iterations = 10;  // after removing chi2 outliers (ORB-SLAM's two stages)
  double chi2_point = 5.991;         // 95 % of chi2 with 2 DoF (ORB-SLAM)
  double chi2_line = 5.991;          // two endpoint distances, 2 DoF
  double huber_delta = 2.447651936;  // sqrt(5.991): Huber on whitened pixel residuals
  // Line direction term: weight on e_dir = 1 - |cos| and the Huber width on the
  // weighted residual (the paper uses a robust loss and no information matrix;
  // the weight is ours). e_dir ~ angle^2 / 2 is flat near zero, so the weight
  // must be large to matter: 1000 makes 1 deg cost like 0.15 px, and with
  // delta 1 the loss turns linear beyond ~2.6 deg (a wrong fusion direction
  // cannot dominate).
  double direction_weight = 1000.0;
  double direction_huber_delta = 1.0;
  bool use_direction_residual = true;  // off only by --ablate direction-residual
  // LiDAR depth of keypoints, used for every observation that has one
  // (residuals/point_depth.h): sigma = ratio * z_lidar, Huber width and
  // outlier bound of the 1-DoF chi2 at 95 %. A depth found to be an outlier
  // drops only its depth term (the LiDAR point under the keypoint may belong
  // to another surface); the reprojection stays.
  double depth_sigma_ratio = 0.02;
  double depth_huber_delta = 1.959963985;  // sqrt(3.841)
  double chi2_depth = 3.841;
  // Pose priors from the LiDAR odometry (residuals/pose_prior.h), for the
  // keyframes that have one: sigma of the camera centre and of the rotation,
  // Huber width of the chi2 with 6 DoF at 95 % (a LiDAR pose that disagrees
  // with the images weighs linearly, not quadratically).
  double prior_sigma_m = 0.01;
  double prior_sigma_deg = 0.2;
  double prior_huber_delta = 3.548519; // sqrt(12.592)
};

struct BaKeyframe {
  Eigen::Isometry3d T_camera_world = Eigen::Isometry3d::Identity();
  bool fixed = false;  // gauge: fix at least the oldest keyframes of the window
  std::optional<Eigen::Isometry3d> prior_T_camera_world;  // from the LiDAR odometry
};

struct BaPoint {
  Eigen::Vector3d p_world = Eigen::Vector3d::Zero();
  bool fixed = false;
};

struct BaLine {
  PluckerLine line_world;
  std::optional<Eigen::Vector3d> fusion_direction;  // d_fu when the fusion framework gave one
  bool fixed = false;
};

// Observations refer to the vectors above by index. Pixels are undistorted.
struct BaPointObservation {
  int keyframe = 0, point = 0;
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
  double inv_sigma2 = 1.0;  // 1 / sigma^2 of the pyramid level
  // LiDAR depth z (camera frame) of the keypoint in this keyframe; NaN: none.
  double depth = std::numeric_limits<double>::quiet_NaN();
};

struct BaLineObservation {
  int keyframe = 0, line = 0;
  Eigen::Vector2d start = Eigen::Vector2d::Zero(), end = Eigen::Vector2d::Zero();
  double inv_sigma2 = 1.0;
};

struct BundleAdjustmentProblem {
  PinholeIntrinsics intrinsics;
  std::vector<BaKeyframe> keyframes;
  std::vector<BaPoint> points;
  std::vector<BaLine> lines;
  std::vector<BaPointObservation> point_observations;
  std::vector<BaLineObservation> line_observations;
};

struct BundleAdjustmentResult {
  bool usable = false;  // the solver ran and the result is finite
  double initial_cost = 0.0, final_cost = 0.0;
  std::vector<bool> point_inlier;  // per point observation
  std::vector<bool> line_inlier;   // per line observation
  std::vector<bool> depth_inlier;  // per point observation: its depth term was used and kept
};

// Optimises the non-fixed keyframes, points and lines of the problem in place
// (lines come back with |(m, d)| = 1). Throws lvslam::Error on an index out of
// range or a finite non-positive depth; observations that cannot be evaluated
// (behind the camera) are outliers.
BundleAdjustmentResult runBundleAdjustment(BundleAdjustmentProblem& problem,
                                           const BundleAdjustmentConfig& config = {});

}  // namespace lvslam::visual
