#include "lvslam/visual/tracking/relocalization.h"

#include <algorithm>

namespace lvslam::visual {

std::vector<Eigen::Isometry3d> relocalizationGuesses(const VisualMap& map, const Eigen::Isometry3d& T_extrapolated,
                                                     const Eigen::Isometry3d& T_last, int reference_keyframe,
                                                     std::size_t neighbours) {
  std::vector<Eigen::Isometry3d> guesses{T_extrapolated, T_last};
  if (!map.hasKeyframe(reference_keyframe)) return guesses;
  guesses.push_back(map.keyframe(reference_keyframe).T_camera_world);
  for (const int kf : map.covisibility().bestNeighbours(reference_keyframe, neighbours))
    guesses.push_back(map.keyframe(kf).T_camera_world);
  return guesses;
}

std::optional<FrameTrackingResult> relocalizeFrame(const VisualMap& map, const LocalMap& local,
                                                   const std::vector<Eigen::Isometry3d>& guesses,
                                                   const PinholeIntrinsics& intrinsics, double radius_scale,
                                                   int min_point_inliers, const FrameTrackerConfig& config,
                                                   TrackedFrame& frame) {
  for (const Eigen::Isometry3d& guess : guesses) {
    FrameTrackingResult tracked = trackLocalMap(map, local, guess, intrinsics, radius_scale, config, frame);
    if (tracked.success && frame.point_inliers >= min_point_inliers) return tracked;
  }
  std::fill(frame.point_landmark.begin(), frame.point_landmark.end(), -1);
  std::fill(frame.line_landmark.begin(), frame.line_landmark.end(), -1);
  frame.point_inliers = frame.line_inliers = 0;
  return std::nullopt;
}

}  // namespace lvslam::visual
