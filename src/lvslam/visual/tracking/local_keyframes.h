#pragma once
// The keyframes whose landmarks a frame is tracked against (ORB-SLAM's
// Tracking::UpdateLocalKeyFrames): those observing the landmarks the last
// frame tracked, most shared first, then the best covisible neighbours of
// the most shared ones. In a turn this follows the view better than the
// covisible neighbours of the last keyframe alone.
#include <cstddef>
#include <vector>

#include "lvslam/visual/data/visual_map.h"

namespace lvslam::visual {

struct LocalKeyframeConfig {
  std::size_t max_voted = 20;         // keyframes sharing landmarks with the last frame
  std::size_t expanded = 10;          // ... of which this many add neighbours
  std::size_t neighbours_each = 3;    // best covisible neighbours per expanded keyframe
};

struct LocalKeyframes {
  std::vector<int> keyframes;  // the reference keyframe first
  int most_shared = -1;        // the keyframe sharing most landmarks, -1 without votes
};

// `tracked_points`: landmark ids of the last tracked frame (bad ones are
// ignored). `reference_keyframe` is always included when it exists.
LocalKeyframes selectLocalKeyframes(const VisualMap& map, const std::vector<int>& tracked_points,
                                    int reference_keyframe, const LocalKeyframeConfig& config = {});

}  // namespace lvslam::visual
