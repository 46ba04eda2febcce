#include "lvslam/visual/tracking/keyframe_policy.h"

namespace lvslam::visual {

bool keyframeNeeded(const KeyframePolicy& policy, int point_inliers, int reference_tracked, int frames_since) {
  if (point_inliers < policy.min_inliers) return false;
  if (frames_since >= policy.max_interval) return true;
  const bool new_ground =
      point_inliers < policy.tracked_ratio * reference_tracked || point_inliers < policy.min_tracked;
  return new_ground && frames_since >= policy.min_interval;
}

}  // namespace lvslam::visual
