#pragma once
// New point landmarks from two keyframes (ORB-SLAM's CreateNewMapPoints
// without bag of words): each keypoint of keyframe 1 without a landmark is
// searched in keyframe 2 around where it would appear at keyframe 1's median
// scene depth, among keypoints near its epipolar line; the best ORB match
// (ratio test, each keypoint once) is triangulated (linear DLT) and kept when
// it lies in front of both cameras with enough parallax and reprojects within
// the chi2 bound in both views.
#include <vector>

#include "lvslam/visual/data/visual_map.h"
#include "lvslam/visual/residuals/pose_block.h"

namespace lvslam::visual {

struct PointTriangulationConfig {
  double search_window_px = 100.0;
  double chi2_epipolar = 3.84;    // 95 % chi2, 1 DoF, on the epipolar distance / sigma
  int max_distance = 50;          // ORB Hamming (ORB-SLAM TH_LOW)
  double ratio = 0.8;
  double min_parallax_cos = 0.9998;  // ORB-SLAM: rays closer than ~1.1 deg are not triangulated
  double chi2_reprojection = 5.991;
  double min_baseline_ratio = 0.01;  // baseline / median depth (ORB-SLAM)
  // Points straight from LiDAR keypoint depths (createDepthPoints): at most
  // this many per keyframe, nearest first (ORB-SLAM2's RGB-D close points).
  // Off by default: they need accurate depths. lvslam run turns them on
  // when keyframe depths are raw deskewed LiDAR points.
  bool create_depth_points = false;
  int max_depth_points = 100;
};

// Returns the new landmark ids; both keyframes observe each.
std::vector<int> triangulateNewPoints(VisualMap& map, int keyframe1, int keyframe2, const PinholeIntrinsics& intrinsics,
                                      const PointTriangulationConfig& config = {});

// New point landmarks from the keyframe's LiDAR keypoint depths
// (Keyframe::keypoint_depth) for keypoints that have none yet, i.e. that
// two-view triangulation could not make: p = T_wc (z K^-1 x) (ORB-SLAM2's
// RGB-D close points). The keyframe observes each; returns their ids.
std::vector<int> createDepthPoints(VisualMap& map, int keyframe, const PinholeIntrinsics& intrinsics,
                                   const PointTriangulationConfig& config = {});

}  // namespace lvslam::visual
