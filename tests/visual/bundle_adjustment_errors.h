#pragma once
// Largest errors of a bundle adjustment estimate against the synthetic scene
// it was built from (camera centres, rotations, points, lines); landmarks
// seen by fewer than two keyframes are not determined and are skipped.
#include <algorithm>
#include <vector>

#include "lvslam/core/se3.h"
#include "lvslam/visual/optimize/bundle_adjustment.h"
#include "visual/synthetic_scene.h"

namespace lvslam::visual::testing {

struct BaErrors {
  double max_translation = 0, max_rotation = 0, max_point = 0, max_line = 0;
};

inline BaErrors baErrors(const BundleAdjustmentProblem& estimate, const SyntheticScene& truth) {
  std::vector<int> point_views(truth.points.size(), 0), line_views(truth.segments.size(), 0);
  for (const auto& o : estimate.point_observations) ++point_views[o.point];
  for (const auto& o : estimate.line_observations) ++line_views[o.line];
  BaErrors e;
  for (size_t k = 0; k < truth.T_camera_world.size(); ++k) {
    const Eigen::Isometry3d d = estimate.keyframes[k].T_camera_world * truth.T_camera_world[k].inverse();
    e.max_translation = std::max(e.max_translation, (estimate.keyframes[k].T_camera_world.inverse().translation() -
                                                     truth.T_camera_world[k].inverse().translation()).norm());
    e.max_rotation = std::max(e.max_rotation, rotationAngle(d));
  }
  for (size_t i = 0; i < truth.points.size(); ++i) {
    if (point_views[i] < 2) continue;
    e.max_point = std::max(e.max_point, (estimate.points[i].p_world - truth.points[i]).norm());
  }
  for (size_t j = 0; j < truth.segments.size(); ++j) {
    if (line_views[j] < 2) continue;
    e.max_line = std::max(e.max_line, sameLineError(estimate.lines[j].line_world, lineOf(truth.segments[j])));
  }
  return e;
}

}  // namespace lvslam::visual::testing
