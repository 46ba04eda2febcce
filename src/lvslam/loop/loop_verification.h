#pragma once
// Geometric verification of a loop candidate: the query keyframe's features
// registered by the LiDAR subsystem's multi-metric ICP onto a small map of
// the candidate keyframe and its neighbours, started at the candidate's
// position turned by the descriptor's yaw. Accepted only when the ICP
// converged with a low residual, enough inliers and no degenerate direction.
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/core/se3.h"
#include "lvslam/lidar/feature_point.h"
#include "lvslam/lidar/lidar_config.h"
#include "lvslam/loop/loop_config.h"
#include "lvslam/loop/loop_keyframe.h"

namespace lvslam::loop {

// A keyframe's features placed in the candidate's LiDAR frame.
struct SubmapScan {
  Eigen::Isometry3d T_candidate_lidar = Eigen::Isometry3d::Identity();
  const std::vector<lidar::FeaturePoint>* points = nullptr;
};

// Keyframes [candidate - neighbours, candidate + neighbours] (within
// [0, last]) placed in the candidate's LiDAR frame; they point into
// `keyframes`, which must outlive the result.
std::vector<SubmapScan> submapAround(const std::vector<LoopKeyframe>& keyframes, int candidate, int neighbours,
                                     int last);

struct LoopVerification {
  bool accepted = false;
  std::string reason;  // why not, empty when accepted
  Eigen::Isometry3d T_candidate_query = Eigen::Isometry3d::Identity();
  double rms = 0.0;           // metres, noise-weighted, at the last threshold
  double inlier_ratio = 0.0;  // correspondences per query feature
  std::size_t correspondences = 0;
  bool degenerate = false;
  double localizability = 0.0;  // IcpResult::localizability
  Matrix6d information = Matrix6d::Zero();  // of T_candidate_query (right perturbation), from the ICP
};

LoopVerification verifyLoop(const std::vector<lidar::FeaturePoint>& query, const std::vector<SubmapScan>& submap,
                            double yaw, const LoopClosureConfig& config, const lidar::RegistrationConfig& registration);

}  // namespace lvslam::loop
