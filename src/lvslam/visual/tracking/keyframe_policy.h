#pragma once
// When a tracked frame becomes a keyframe (ORB-SLAM's rule c2 with a frame
// interval), and the settings of that rule: "visual: keyframes:" in
// config/*.yaml. Intervals count camera frames, so a faster camera wants
// larger ones.

namespace lvslam::visual {

struct KeyframePolicy {
  // A frame tracking fewer points than this share of what the reference
  // keyframe tracked when it was inserted, or fewer than min_tracked, sees
  // new ground (ORB-SLAM's c2: 0.9).
  double tracked_ratio = 0.9;
  int min_tracked = 100;
  // Such a frame is a keyframe once min_interval frames have passed since the
  // last one; any frame is after max_interval. Max 5: longer intervals cost
  // accuracy (docs/history/2026-11-21-components.md, "Visual speed").
  int min_interval = 3;
  int max_interval = 5;
  // Fewer point inliers than this: never a keyframe (ORB-SLAM asks for more than 15).
  int min_inliers = 16;
};

// point_inliers: the frame's tracked points; reference_tracked: what the
// reference keyframe tracked; frames_since: frames since the last keyframe.
bool keyframeNeeded(const KeyframePolicy& policy, int point_inliers, int reference_tracked, int frames_since);

}  // namespace lvslam::visual
