#pragma once
// VisualSlam's settings: the algorithm settings (VisualConfig) plus those of
// the tracking loop (initialisation, tracking windows, relocalisation) and of
// the mapping modules it runs.
#include <cstddef>

#include "lvslam/visual/module/line_depth_check.h"
#include "lvslam/visual/module/map_culling.h"
#include "lvslam/visual/module/point_triangulation.h"
#include "lvslam/visual/tracking/image_statistics.h"
#include "lvslam/visual/visual_config.h"

namespace lvslam::visual {

struct VisualSlamConfig {
  VisualConfig modules;  // the tracking and mapping modules' settings
  ImageUsabilityConfig usability;
  int min_keypoints = 100;  // fewer: the frame is not usable (featureless, blurred)
  // Initialisation (ORB-SLAM): matches reference -> current in a window.
  double init_window_px = 100.0;
  int min_init_matches = 100;
  int max_init_frames = 30;     // a reference older than this is replaced
  // A keypoint's depth is read from the hints this close (surfaceDepths).
  double depth_radius_px = 8.0;
  // A frame whose hints give this share of its keypoints a depth starts a map
  // alone (ORB-SLAM2's RGB-D start asks 500 of its 1000 keypoints; a LiDAR
  // reaches fewer): fewer, and the sweep was elsewhere at its time.
  double min_depth_share = 0.25;
  // A frame given hints of which too few reach keypoints is passed over as
  // the first view, at most this many times in a row.
  int max_unhinted_references = 10;
  // Tracking.
  double search_radius_px = 15.0;
  double refine_radius_px = 5.0;
  // ORB distance a projected landmark's match may have (ORB-SLAM's TH_HIGH in
  // SearchByProjection: the window already tells where to look; the tighter
  // TH_LOW of point_matching is for matches without a pose).
  int track_max_distance = 100;
  double recovery_radius_scale = 3.0;  // wider window after a failure / when lost
  int min_tracked = 30;                // point + line inliers
  // Lost: relocalisation into the old map for this many frames, then a new map.
  int relocalize_frames = 15;
  size_t relocalize_candidates = 4;  // covisible neighbours of the reference keyframe tried as pose guesses
  int relocalize_min_inliers = 50;   // point inliers to accept a relocalisation (ORB-SLAM: 50)
  int fusion_line_lifetime = 15;  // frames a fusion line waits for a keyframe observation
  size_t lidar_pose_buffer = 64;  // LiDAR poses kept for keyframes (> init window + LiDAR lag)
  PointTriangulationConfig triangulation;
  CullingConfig culling;
  LineDepthCheckConfig depth_check;
};

}  // namespace lvslam::visual
