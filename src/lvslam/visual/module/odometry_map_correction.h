#pragma once
// Map correction with the LiDAR odometry (lvslam's addition,
// docs/visual-subsystem.md "LiDAR pose priors"): the newest keyframes of the
// visual map enter a pose graph (optimize/odometry_pose_graph.h) with edges
// between covisible and consecutive keyframes and the LiDAR odometry's poses
// as priors; the landmarks then move rigidly with their first observer. Local
// BA alone cannot remove the drift: the keyframes outside its window are
// fixed and hold it. Older keyframes were corrected while they were new: the
// ones linked to the window hold still in the graph and anchor it, so a
// correction costs the same at any map size.
#include <unordered_map>

#include "lvslam/visual/data/visual_map.h"
#include "lvslam/visual/optimize/odometry_pose_graph.h"

namespace lvslam::visual {

struct MapCorrectionConfig {
  int every_keyframes = 10;    // a correction after this many new keyframes; 0: never
  int min_covisibility = 50;   // landmarks two keyframes share to be an edge
  int window_keyframes = 50;   // the newest keyframes corrected; 0: the whole map
  PoseGraphConfig graph;
};

struct MapCorrectionResult {
  PoseGraphResult graph;
  // Per keyframe id, when solved: the world motion T_new_old of everything
  // the keyframe carries (p_new = T_new_old p_old).
  std::unordered_map<int, Eigen::Isometry3d> T_new_old;
  int keyframes = 0;        // corrected (the window)
  int held_keyframes = 0;   // older ones linked to the window, held still
  double max_shift_m = 0.0, max_rotation_deg = 0.0;  // largest keyframe correction
};

MapCorrectionResult correctMapWithOdometry(VisualMap& map, const MapCorrectionConfig& config);

}  // namespace lvslam::visual
