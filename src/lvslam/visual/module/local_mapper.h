#pragma once
// The local mapper, run in the tracking thread on every new keyframe
// (ORB-SLAM's LocalMapping made synchronous, hence deterministic): new point
// landmarks by triangulation with the covisible keyframes, new line landmarks
// from LBD matches and dual-Plücker triangulation, local BA, endpoint
// trimming, Structure PLP's line depth check, culling of recent landmarks and
// of redundant keyframes (Cao et al., Sec. III-D).
#include <vector>

#include "lvslam/visual/data/visual_map.h"
#include "lvslam/visual/match/line_matcher.h"
#include "lvslam/visual/module/line_depth_check.h"
#include "lvslam/visual/module/line_landmark_creation.h"
#include "lvslam/visual/module/map_culling.h"
#include "lvslam/visual/module/point_merging.h"
#include "lvslam/visual/module/point_triangulation.h"
#include "lvslam/visual/optimize/local_window_adjustment.h"

namespace lvslam::visual {

struct LocalMapperConfig {
  size_t point_neighbours = 10; // covisible keyframes searched for new points
  size_t line_neighbours = 2;   // ... and for new lines
  PointTriangulationConfig points;
  PointMergingConfig merging;
  LineCreationConfig lines;
  LineMatcherConfig line_matching;
  LocalWindowConfig window;
  CullingConfig culling;
  LineDepthCheckConfig depth_check;
  bool cull_keyframes = true;
};

struct LocalMappingResult {
  int new_points = 0, new_lines = 0;
  int added_observations = 0, merged_points = 0;
  int culled_points = 0, culled_lines = 0, depth_outlier_lines = 0;
  std::vector<int> removed_keyframes;
  bool ba_usable = false;
};

class LocalMapper {
 public:
  LocalMapper(const LocalMapperConfig& config, const PinholeIntrinsics& intrinsics);

  // `keyframe` is in the map with the observations tracking found.
  LocalMappingResult process(VisualMap& map, int keyframe);

  // Landmarks created elsewhere (map initialisation, fusion lines) enter the
  // recent-landmark tests from `keyframe` on.
  void addRecentPoints(const std::vector<int>& ids, int keyframe);
  void addRecentLines(const std::vector<int>& ids, int keyframe);
  // Per tracked frame: which recent landmarks were visible and which were found.
  void countTracking(const std::vector<int>& visible_points, const std::vector<int>& found_points,
                     const std::vector<int>& visible_lines, const std::vector<int>& found_lines);
  void reset();

 private:
  void createLandmarks(VisualMap& map, int keyframe, LocalMappingResult& result);
  void trimLines(VisualMap& map, const std::vector<int>& window) const;

  LocalMapperConfig config_;
  PinholeIntrinsics K_;
  UsageTable recent_points_, recent_lines_;
};

}  // namespace lvslam::visual
