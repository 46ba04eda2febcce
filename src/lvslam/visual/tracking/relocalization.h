#pragma once
// Relocalisation without bag of words (lvslam's stand-in for ORB-SLAM's
// Relocalization): the old map is projected around a few pose guesses with a
// wide window and the pose optimised; the first guess that gives enough point
// inliers wins, so the map (and its id) is kept after a short loss.
#include <cstddef>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/visual/data/visual_map.h"
#include "lvslam/visual/tracking/frame_tracker.h"

namespace lvslam::visual {

// The guesses, most likely first: the motion model's pose for this frame
// (T_extrapolated: the last pose carried over the time lost), the last pose,
// the reference keyframe's pose and those of its `neighbours` best covisible
// keyframes.
std::vector<Eigen::Isometry3d> relocalizationGuesses(const VisualMap& map, const Eigen::Isometry3d& T_extrapolated,
                                                     const Eigen::Isometry3d& T_last, int reference_keyframe,
                                                     std::size_t neighbours);

// Tracks `frame` against `local` from each guess in turn (first window
// `radius_scale` times the usual); the first result with at least
// `min_point_inliers` point inliers is returned, with the frame's pose and
// associations set. None: the frame has no associations.
std::optional<FrameTrackingResult> relocalizeFrame(const VisualMap& map, const LocalMap& local,
                                                   const std::vector<Eigen::Isometry3d>& guesses,
                                                   const PinholeIntrinsics& intrinsics, double radius_scale,
                                                   int min_point_inliers, const FrameTrackerConfig& config,
                                                   TrackedFrame& frame);

}  // namespace lvslam::visual
