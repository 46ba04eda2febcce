#pragma once
// Map maintenance of the local mapper (ORB-SLAM's MapPointCulling and
// KeyFrameCulling, applied to points and lines alike): recently created
// landmarks must be found in enough of the frames they were visible in and
// be observed by enough keyframes; keyframes whose landmarks are nearly all
// seen by enough other keyframes are redundant.
#include <algorithm>
#include <unordered_map>
#include <vector>

#include "lvslam/visual/data/visual_map.h"

namespace lvslam::visual {

struct CullingConfig {
  double min_found_ratio = 0.25;  // found / visible (ORB-SLAM)
  int probation_keyframes = 2;    // after this many keyframes ...
  int min_observations = 2;       // ... fewer observing keyframes: culled (ORB-SLAM mono: <= 2; ours is looser)
  int release_keyframes = 3;      // after this many keyframes a landmark is no longer "recent"
  double redundant_ratio = 0.9;   // keyframe culling: share of landmarks seen elsewhere
  int redundant_observers = 3;    // ... by at least this many other keyframes
};

// Tracking statistics of a recent landmark. Keyframe ids grow with time, so
// id differences count keyframes.
struct LandmarkUsage {
  int first_keyframe = 0;
  int visible = 1, found = 1;
};
using UsageTable = std::unordered_map<int, LandmarkUsage>;

// Culls recent points / lines failing the tests and drops landmarks from the
// table once they are no longer recent. Returns the number culled.
int cullRecentPoints(VisualMap& map, UsageTable& recent, int current_keyframe, const CullingConfig& config);
int cullRecentLines(VisualMap& map, UsageTable& recent, int current_keyframe, const CullingConfig& config);

// Removes redundant keyframes among `candidates` (never `keep`, the newest,
// nor the map's first keyframe). Returns the removed ids.
std::vector<int> cullRedundantKeyframes(VisualMap& map, const std::vector<int>& candidates, int keep,
                                        const CullingConfig& config);

}  // namespace lvslam::visual
