#pragma once
// Landmark fusion between a new keyframe and its neighbours (ORB-SLAM's
// LocalMapping::SearchInNeighbors with ORBmatcher::Fuse, points only): the
// new keyframe's points are projected into its first- and second-order
// covisible keyframes and theirs into it; a projection that meets a keypoint
// with a close ORB descriptor adds an observation, or merges the two
// landmarks when that keypoint already has one. Longer tracks and no
// duplicates give local BA the constraints that keep monocular scale.
#include <cstddef>
#include <vector>

#include "lvslam/visual/data/visual_map.h"
#include "lvslam/visual/residuals/pose_block.h"

namespace lvslam::visual {

struct PointMergingConfig {
  std::size_t neighbours = 10;        // first-order covisible keyframes (ORB-SLAM mono: 20)
  std::size_t second_neighbours = 5;  // best neighbours of each of them
  int max_distance = 50;              // ORB Hamming (ORB-SLAM TH_LOW)
  double chi2 = 5.991;                // reprojection test at the keypoint's level (2 DoF, 95 %)
};

struct PointMergingResult {
  int added = 0;   // new observations of existing landmarks
  int merged = 0;  // duplicate landmarks replaced
};

// Projects `points` (landmark ids) into `keyframe` and fuses as described above.
PointMergingResult fusePointsIntoKeyframe(VisualMap& map, int keyframe, const std::vector<int>& points,
                                          const PinholeIntrinsics& intrinsics, const PointMergingConfig& config = {});

// Both directions between `keyframe` and its neighbourhood.
PointMergingResult mergeWithNeighbours(VisualMap& map, int keyframe, const PinholeIntrinsics& intrinsics,
                                       const PointMergingConfig& config = {});

}  // namespace lvslam::visual
