#pragma once
// The keyframes whose landmarks a frame is tracked against (ORB-SLAM's
// Tracking::UpdateLocalKeyFrames): those observing the landmarks the last
// frame tracked, most shared first, then the best covisible neighbours of
// the most shared ones. In a turn this follows the view better than the
// covisible neighbours of the last keyframe alone.
//
// Nearby keyframes add map reuse when a path comes back to where it has
// been: keyframes whose centre lies near the predicted camera and that look
// the same way join the local map, so their landmarks are matched again
// instead of being mapped twice (the covisibility graph alone never links
// back to them once drift has broken the chain of shared landmarks).
#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/visual/data/visual_map.h"

namespace lvslam::visual {

struct LocalKeyframeConfig {
  std::size_t max_voted = 20;         // keyframes sharing landmarks with the last frame
  std::size_t expanded = 10;          // ... of which this many add neighbours
  std::size_t neighbours_each = 3;    // best covisible neighbours per expanded keyframe
  // Nearby keyframes: centre within this many reference-keyframe median scene
  // depths of the predicted camera (scale-free, so it holds for a monocular
  // map); 0 turns map reuse off.
  double nearby_radius_depths = 0.35;
  double nearby_max_angle_deg = 35.0;  // between the optical axes
  std::size_t nearby_max = 6;          // the closest ones
  // Only keyframes at least this many keyframes older than the newest: the
  // recent ones are reached through shared landmarks already, and would
  // crowd out the old ones that map reuse is for.
  std::size_t nearby_min_age = 60;
};

struct LocalKeyframes {
  std::vector<int> keyframes;  // the reference keyframe first
  int most_shared = -1;        // the keyframe sharing most landmarks, -1 without votes
};

// `tracked_points`: landmark ids of the last tracked frame (removed ones are
// ignored). `reference_keyframe` is always included when it exists.
LocalKeyframes selectLocalKeyframes(const VisualMap& map, const std::vector<int>& tracked_points,
                                    int reference_keyframe, const LocalKeyframeConfig& config = {});

// Keyframes whose camera centre is within `radius` of T_camera_world's and
// whose optical axis is within config.nearby_max_angle_deg of its, closest
// first, at most config.nearby_max; not those in `exclude` nor the
// config.nearby_min_age newest. None when radius <= 0.
std::vector<int> nearbyKeyframes(const VisualMap& map, const Eigen::Isometry3d& T_camera_world, double radius,
                                 const std::vector<int>& exclude, const LocalKeyframeConfig& config = {});

}  // namespace lvslam::visual
