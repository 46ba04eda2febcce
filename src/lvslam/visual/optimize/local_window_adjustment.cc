#include "lvslam/visual/optimize/local_window_adjustment.h"

#include <algorithm>
#include <limits>
#include <map>

namespace lvslam::visual {

namespace {

struct ObservationRef {
  int keyframe = -1, landmark = -1;  // map ids
};

// Map ids of the BA problem's entries, to copy results back.
struct WindowIndex {
  std::map<int, int> keyframe, point, line;  // map id -> problem index
  std::vector<int> keyframe_ids, point_ids, line_ids;
  std::vector<ObservationRef> point_obs, line_obs;  // per problem observation
};

int indexOf(std::map<int, int>& index, std::vector<int>& ids, int id) {
  const auto [it, inserted] = index.emplace(id, static_cast<int>(ids.size()));
  if (inserted) ids.push_back(id);
  return it->second;
}

void collectLandmarks(const VisualMap& map, const std::vector<int>& window, BundleAdjustmentProblem& problem,
                      WindowIndex& idx) {
  for (const int kf : window) {
    const Keyframe& k = map.keyframe(kf);
    for (const int p : k.point_landmark) {
      if (p >= 0 && idx.point.count(p) == 0) {
        indexOf(idx.point, idx.point_ids, p);
        problem.points.push_back({map.point(p).p_world, false});
      }
    }
    for (const int l : k.line_landmark) {
      if (l >= 0 && idx.line.count(l) == 0) {
        indexOf(idx.line, idx.line_ids, l);
        const LineLandmark& line = map.line(l);
        problem.lines.push_back({line.line_world, line.fusion_direction, false});
      }
    }
  }
}

int keyframeIndex(const VisualMap& map, int kf, BundleAdjustmentProblem& problem, WindowIndex& idx) {
  const auto it = idx.keyframe.find(kf);
  if (it != idx.keyframe.end()) return it->second;
  problem.keyframes.push_back({map.keyframe(kf).T_camera_world, true, std::nullopt});  // outside the window: fixed
  return indexOf(idx.keyframe, idx.keyframe_ids, kf);
}

void collectObservations(const VisualMap& map, BundleAdjustmentProblem& problem, WindowIndex& idx) {
  for (size_t j = 0; j < idx.point_ids.size(); ++j) {
    for (const Observation& o : map.point(idx.point_ids[j]).observations) {
      const Keyframe& k = map.keyframe(o.keyframe);
      const int level = k.features.keypoints[o.index].octave;
      const auto& inv = k.features.pyramid.inv_sigma2;
      const double inv_sigma2 = level >= 0 && static_cast<size_t>(level) < inv.size() ? inv[level] : 1.0;
      const double depth = static_cast<size_t>(o.index) < k.keypoint_depth.size()
                               ? k.keypoint_depth[o.index]
                               : std::numeric_limits<double>::quiet_NaN();
      problem.point_observations.push_back({keyframeIndex(map, o.keyframe, problem, idx), static_cast<int>(j),
                                            k.features.points[o.index], inv_sigma2, depth});
      idx.point_obs.push_back({o.keyframe, idx.point_ids[j]});
    }
  }
  for (size_t j = 0; j < idx.line_ids.size(); ++j) {
    for (const Observation& o : map.line(idx.line_ids[j]).observations) {
      const LineSegment& s = map.keyframe(o.keyframe).features.lines[o.index];
      problem.line_observations.push_back(
          {keyframeIndex(map, o.keyframe, problem, idx), static_cast<int>(j), s.start, s.end, 1.0});
      idx.line_obs.push_back({o.keyframe, idx.line_ids[j]});
    }
  }
}

}  // namespace

LocalWindowResult adjustLocalWindow(VisualMap& map, int keyframe, const PinholeIntrinsics& intrinsics,
                                    const LocalWindowConfig& config) {
  LocalWindowResult result;
  std::vector<int> window = map.localWindow(keyframe, config.window_size);
  std::sort(window.begin(), window.end());  // by id = by age
  BundleAdjustmentProblem problem;
  problem.intrinsics = intrinsics;
  WindowIndex idx;
  for (const int kf : window) {
    problem.keyframes.push_back({map.keyframe(kf).T_camera_world, false, map.odometryPrior(kf)});
    indexOf(idx.keyframe, idx.keyframe_ids, kf);
  }
  collectLandmarks(map, window, problem, idx);
  collectObservations(map, problem, idx);
  result.fixed_keyframes = static_cast<int>(problem.keyframes.size() - window.size());
  if (result.fixed_keyframes == 0) {
    for (int i = 0; i < config.fixed_oldest && i < static_cast<int>(window.size()); ++i) {
      problem.keyframes[i].fixed = true;
      ++result.fixed_keyframes;
    }
  }
  result.optimised_keyframes = static_cast<int>(problem.keyframes.size()) - result.fixed_keyframes;

  const BundleAdjustmentResult ba = runBundleAdjustment(problem, config.ba);
  result.usable = ba.usable;
  if (!ba.usable) return result;
  for (size_t k = 0; k < idx.keyframe_ids.size(); ++k) {
    if (!problem.keyframes[k].fixed) map.keyframe(idx.keyframe_ids[k]).T_camera_world = problem.keyframes[k].T_camera_world;
  }
  for (size_t j = 0; j < idx.point_ids.size(); ++j) map.point(idx.point_ids[j]).p_world = problem.points[j].p_world;
  for (size_t j = 0; j < idx.line_ids.size(); ++j) map.line(idx.line_ids[j]).line_world = problem.lines[j].line_world;
  for (size_t i = 0; i < ba.point_inlier.size(); ++i) {
    if (ba.point_inlier[i]) continue;
    map.removePointObservation(idx.point_obs[i].landmark, idx.point_obs[i].keyframe);
    ++result.removed_point_observations;
  }
  for (size_t i = 0; i < ba.line_inlier.size(); ++i) {
    if (ba.line_inlier[i]) continue;
    map.removeLineObservation(idx.line_obs[i].landmark, idx.line_obs[i].keyframe);
    ++result.removed_line_observations;
  }
  return result;
}

}  // namespace lvslam::visual
