#include "lvslam/visual/module/point_merging.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "lvslam/visual/match/descriptor_distance.h"
#include "lvslam/visual/match/feature_grid.h"

namespace lvslam::visual {

namespace {

bool observedBy(const PointLandmark& p, int keyframe) {
  return std::any_of(p.observations.begin(), p.observations.end(),
                     [&](const Observation& o) { return o.keyframe == keyframe; });
}

// ORB-SLAM's viewing-angle test: the new view must be within 60 deg of the
// mean direction the landmark has been seen from.
bool viewedSimilarly(const VisualMap& map, const PointLandmark& p, const Eigen::Vector3d& camera_center) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Observation& o : p.observations)
    mean += (p.p_world - map.keyframe(o.keyframe).T_camera_world.inverse().translation()).normalized();
  if (!(mean.norm() > 0.0)) return true;
  return (p.p_world - camera_center).normalized().dot(mean.normalized()) >= 0.5;
}

double levelScale(const FeatureFrame& f, int keypoint) {
  const int level = f.keypoints[keypoint].octave;
  return level >= 0 && static_cast<size_t>(level) < f.pyramid.scale.size() ? f.pyramid.scale[level] : 1.0;
}

// The keypoint of `k` that best matches landmark `p` projected at `pixel`, or -1.
int bestKeypoint(const Keyframe& k, const FeatureGrid& grid, const PointLandmark& p, const Eigen::Vector2d& pixel,
                 double radius, const PointMergingConfig& config, std::vector<int>& candidates) {
  grid.query(pixel, radius, candidates);
  int best = -1, best_distance = std::numeric_limits<int>::max();
  for (const int j : candidates) {
    const double s = levelScale(k.features, j);
    if ((k.features.points[j] - pixel).squaredNorm() > config.chi2 * s * s) continue;
    const int d = hammingDistance256(p.descriptor.ptr<uint8_t>(0), k.features.descriptors.ptr<uint8_t>(j));
    if (d < best_distance) {
      best_distance = d;
      best = j;
    }
  }
  return best_distance <= config.max_distance ? best : -1;
}

}  // namespace

PointMergingResult fusePointsIntoKeyframe(VisualMap& map, int keyframe, const std::vector<int>& points,
                                          const PinholeIntrinsics& K, const PointMergingConfig& config) {
  PointMergingResult result;
  const Keyframe& k = map.keyframe(keyframe);
  const FeatureFrame& f = k.features;
  if (f.points.empty() || f.descriptors.rows != static_cast<int>(f.points.size())) return result;
  const FeatureGrid grid(f.points, f.width, f.height);
  const double max_scale = f.pyramid.scale.empty() ? 1.0 : f.pyramid.scale.back();
  const double radius = std::sqrt(config.chi2) * max_scale;
  const Eigen::Vector3d center = k.T_camera_world.inverse().translation();
  std::vector<int> candidates;
  for (const int id : points) {
    if (!map.hasPoint(id)) continue;  // merged away earlier in this loop
    const PointLandmark& p = map.point(id);
    if (p.descriptor.empty() || observedBy(p, keyframe)) continue;
    const Eigen::Vector3d pc = k.T_camera_world * p.p_world;
    if (!(pc.z() > 0.05)) continue;
    const Eigen::Vector2d pixel(K.fx * pc.x() / pc.z() + K.cx, K.fy * pc.y() / pc.z() + K.cy);
    if (!(pixel.x() >= 0.0 && pixel.y() >= 0.0 && pixel.x() < f.width && pixel.y() < f.height)) continue;
    if (!viewedSimilarly(map, p, center)) continue;
    const int j = bestKeypoint(k, grid, p, pixel, radius, config, candidates);
    if (j < 0) continue;
    const int other = k.point_landmark[j];
    if (other < 0) {
      map.addPointObservation(id, keyframe, j);
      ++result.added;
    } else if (other != id) {
      // The better observed landmark survives (ORB-SLAM's Fuse).
      if (map.point(other).observations.size() >= p.observations.size()) {
        map.replacePoint(id, other);
      } else {
        map.replacePoint(other, id);
      }
      ++result.merged;
    }
  }
  return result;
}

PointMergingResult mergeWithNeighbours(VisualMap& map, int keyframe, const PinholeIntrinsics& K,
                                       const PointMergingConfig& config) {
  std::vector<int> targets = map.covisibility().bestNeighbours(keyframe, config.neighbours);
  std::set<int> seen(targets.begin(), targets.end());
  seen.insert(keyframe);
  const size_t first_order = targets.size();
  for (size_t i = 0; i < first_order; ++i) {
    for (const int kf : map.covisibility().bestNeighbours(targets[i], config.second_neighbours))
      if (seen.insert(kf).second) targets.push_back(kf);
  }
  PointMergingResult total;
  const auto accumulate = [&](const PointMergingResult& r) {
    total.added += r.added;
    total.merged += r.merged;
  };
  std::vector<int> own;
  for (const int p : map.keyframe(keyframe).point_landmark)
    if (p >= 0) own.push_back(p);
  for (const int kf : targets) accumulate(fusePointsIntoKeyframe(map, kf, own, K, config));
  std::set<int> theirs;
  for (const int kf : targets)
    for (const int p : map.keyframe(kf).point_landmark)
      if (p >= 0) theirs.insert(p);
  accumulate(fusePointsIntoKeyframe(map, keyframe, {theirs.begin(), theirs.end()}, K, config));
  return total;
}

}  // namespace lvslam::visual
