#pragma once
// Tracking one frame against the local map (ORB-SLAM's TrackWithMotionModel
// + TrackLocalMap in one step): the landmarks the local keyframes observe are
// projected with a predicted pose, matched in a window (ORB distance for
// points, LBD for lines), the pose is optimised on point reprojection and
// line e_dis with robust kernels and chi2 outlier rejection, then the map is
// projected again with the refined pose in a tight window for more matches
// and the pose optimised once more.
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/visual/data/visual_map.h"
#include "lvslam/visual/feature/feature_frame.h"
#include "lvslam/visual/match/feature_grid.h"
#include "lvslam/visual/match/line_matcher.h"
#include "lvslam/visual/match/point_matcher.h"
#include "lvslam/visual/optimize/pose_optimization.h"

namespace lvslam::visual {

struct FrameTrackerConfig {
  double search_radius_px = 15.0;  // first pass, around the constant-velocity prediction
  double refine_radius_px = 5.0;   // second pass, around the optimised pose
  int min_inliers = 30;            // points + lines after the last optimisation
  double line_distance_scale = 1.0;  // multiplies LineMatcherConfig::max_line_distance_px in the first pass
  PointMatcherConfig point_matching;
  LineMatcherConfig line_matching;
  PoseOptimizationConfig pose;
};

// A frame being tracked: features, pose and per feature its landmark (-1: none).
struct TrackedFrame {
  FeatureFrame features;
  FeatureGrid grid;
  Eigen::Isometry3d T_camera_world = Eigen::Isometry3d::Identity();
  std::vector<int> point_landmark, line_landmark;
  int point_inliers = 0, line_inliers = 0;
  // The last pose optimisation's information (PoseOptimizationResult), when
  // the pose came from tracking.
  std::optional<Matrix6d> information;
};

// An inlier of a frame's last pose optimisation: the landmark and the frame's
// measurement of it (undistorted pixels), kept to optimise the frame's pose
// again once the landmarks have moved (relocateInMap).
struct TrackedPointObservation {
  int landmark = -1;
  Eigen::Vector2f pixel = Eigen::Vector2f::Zero();
  float inv_sigma2 = 1.0f;
};
struct TrackedLineObservation {
  int landmark = -1;
  Eigen::Vector2f start = Eigen::Vector2f::Zero(), end = Eigen::Vector2f::Zero();
};
struct TrackedObservations {
  std::vector<TrackedPointObservation> points;
  std::vector<TrackedLineObservation> lines;
};
// The frame's landmark associations (its inliers) as measurements.
TrackedObservations trackedObservations(const TrackedFrame& frame);

// The pose T_camera_world of a frame with these observations, optimised from
// T_initial against the map's landmarks as they stand now (removed ones skipped),
// with the tracker's pose optimisation. None when it fails or keeps fewer than
// min_inliers inliers.
std::optional<Eigen::Isometry3d> relocateInMap(const VisualMap& map, const TrackedObservations& observations,
                                               const Eigen::Isometry3d& T_initial, const PinholeIntrinsics& intrinsics,
                                               const FrameTrackerConfig& config);

// Landmark ids to track against.
struct LocalMap {
  std::vector<int> points, lines;
};

// Landmarks seen by `keyframe` and its n - 1 best covisible neighbours, plus
// `extra_lines` (fusion lines not yet observed by a keyframe).
LocalMap collectLocalMap(const VisualMap& map, int keyframe, size_t n, const std::vector<int>& extra_lines);
// Landmarks seen by any of `keyframes`, plus `extra_lines`.
LocalMap collectLocalMap(const VisualMap& map, const std::vector<int>& keyframes, const std::vector<int>& extra_lines);

struct FrameTrackingResult {
  bool success = false;
  int matches = 0;  // point + line matches of the last pass (before outlier rejection)
  std::vector<int> visible_points, visible_lines;  // projected inside the image (ORB-SLAM's "visible")
};

// Fills frame.point_landmark / line_landmark with the inliers and sets
// frame.T_camera_world on success. `radius_scale` widens the first pass
// (recovery after a failure).
FrameTrackingResult trackLocalMap(const VisualMap& map, const LocalMap& local, const Eigen::Isometry3d& T_predicted,
                                  const PinholeIntrinsics& intrinsics, double radius_scale,
                                  const FrameTrackerConfig& config, TrackedFrame& frame);

}  // namespace lvslam::visual
