#include "lvslam/visual/module/point_triangulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <Eigen/SVD>

#include "lvslam/visual/match/descriptor_distance.h"
#include "lvslam/visual/match/feature_grid.h"

namespace lvslam::visual {

namespace {

struct Candidate {
  int index1 = -1, index2 = -1, distance = std::numeric_limits<int>::max();
};

double levelScale(const FeatureFrame& f, int keypoint) {
  const int level = f.keypoints[keypoint].octave;
  return level >= 0 && static_cast<size_t>(level) < f.pyramid.scale.size() ? f.pyramid.scale[level] : 1.0;
}

// Linear triangulation from two normalised rays (Hartley & Zisserman 12.2).
Eigen::Vector3d triangulateDlt(const Eigen::Isometry3d& T1, const Eigen::Vector2d& x1, const Eigen::Isometry3d& T2,
                               const Eigen::Vector2d& x2) {
  Eigen::Matrix4d A;
  const Eigen::Matrix<double, 3, 4> P1 = T1.matrix().topRows<3>(), P2 = T2.matrix().topRows<3>();
  A.row(0) = x1.x() * P1.row(2) - P1.row(0);
  A.row(1) = x1.y() * P1.row(2) - P1.row(1);
  A.row(2) = x2.x() * P2.row(2) - P2.row(0);
  A.row(3) = x2.y() * P2.row(2) - P2.row(1);
  const Eigen::Vector4d X = Eigen::JacobiSVD<Eigen::Matrix4d>(A, Eigen::ComputeFullV).matrixV().col(3);
  return X.head<3>() / X(3);
}

bool reprojectsWell(const Eigen::Isometry3d& T, const Eigen::Vector3d& p_world, const Eigen::Vector2d& pixel,
                    double scale, const PinholeIntrinsics& K, double chi2) {
  const Eigen::Vector3d p = T * p_world;
  if (!(p.z() > 0.0)) return false;
  const Eigen::Vector2d e(K.fx * p.x() / p.z() + K.cx - pixel.x(), K.fy * p.y() / p.z() + K.cy - pixel.y());
  return e.squaredNorm() / (scale * scale) <= chi2;
}

Eigen::Vector2d normalised(const Eigen::Vector2d& px, const PinholeIntrinsics& K) {
  return {(px.x() - K.cx) / K.fx, (px.y() - K.cy) / K.fy};
}

// Best keypoint of keyframe 2 for keypoint i of keyframe 1 (see header).
Candidate searchPartner(const Keyframe& k1, const Keyframe& k2, const FeatureGrid& grid2, int i,
                        const Eigen::Isometry3d& T21, const Eigen::Matrix3d& F21, double depth,
                        const PinholeIntrinsics& K, const PointTriangulationConfig& config,
                        std::vector<int>& candidates) {
  Candidate best;
  const Eigen::Vector2d& x1 = k1.features.points[i];
  const Eigen::Vector3d p2 = T21 * (depth * Eigen::Vector3d(normalised(x1, K).homogeneous()));
  if (!(p2.z() > 0.0)) return best;
  const Eigen::Vector2d predicted(K.fx * p2.x() / p2.z() + K.cx, K.fy * p2.y() / p2.z() + K.cy);
  const Eigen::Vector3d l2 = F21 * x1.homogeneous();
  const double l2_norm = l2.head<2>().norm();
  if (!(l2_norm > 0.0)) return best;
  grid2.query(predicted, config.search_window_px, candidates);
  int second = std::numeric_limits<int>::max();
  for (const int j : candidates) {
    if (k2.point_landmark[j] >= 0) continue;
    const double scale = levelScale(k2.features, j);
    const double epipolar = l2.dot(k2.features.points[j].homogeneous()) / l2_norm;
    if (epipolar * epipolar > config.chi2_epipolar * scale * scale) continue;
    const int d = descriptorDistance(k1.features.descriptors, i, k2.features.descriptors, j);
    if (d < best.distance) {
      second = best.distance;
      best = {i, j, d};
    } else if (d < second) {
      second = d;
    }
  }
  const bool unique = second == std::numeric_limits<int>::max() || best.distance < config.ratio * second;
  if (best.distance > config.max_distance || !unique) best.index2 = -1;
  return best;
}

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d S;
  S << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return S;
}

}  // namespace

std::vector<int> createDepthPoints(VisualMap& map, int keyframe, const PinholeIntrinsics& K,
                                   const PointTriangulationConfig& config) {
  std::vector<int> created;
  const Keyframe& k = map.keyframe(keyframe);
  if (!config.create_depth_points || k.keypoint_depth.size() != k.features.points.size()) return created;
  std::vector<std::pair<double, int>> candidates;  // (depth, keypoint)
  for (size_t i = 0; i < k.keypoint_depth.size(); ++i) {
    const double z = k.keypoint_depth[i];
    if (k.point_landmark[i] < 0 && std::isfinite(z) && z > 0.0) candidates.emplace_back(z, static_cast<int>(i));
  }
  std::sort(candidates.begin(), candidates.end());
  if (candidates.size() > static_cast<size_t>(std::max(0, config.max_depth_points)))
    candidates.resize(static_cast<size_t>(std::max(0, config.max_depth_points)));
  const Eigen::Isometry3d T_world_camera = k.T_camera_world.inverse();
  for (const auto& [z, i] : candidates) {
    const Eigen::Vector3d p_camera = z * normalised(k.features.points[i], K).homogeneous();
    const int id = map.addPointLandmark(T_world_camera * p_camera, k.features.descriptors.row(i));
    map.addPointObservation(id, keyframe, i);
    created.push_back(id);
  }
  return created;
}

std::vector<int> triangulateNewPoints(VisualMap& map, int keyframe1, int keyframe2, const PinholeIntrinsics& K,
                                      const PointTriangulationConfig& config) {
  std::vector<int> created;
  const Keyframe& k1 = map.keyframe(keyframe1);
  const Keyframe& k2 = map.keyframe(keyframe2);
  const double depth = medianSceneDepth(map, keyframe1);
  const Eigen::Isometry3d T21 = k2.T_camera_world * k1.T_camera_world.inverse();
  if (!(depth > 0.0) || T21.translation().norm() / depth < config.min_baseline_ratio) return created;
  Eigen::Matrix3d Kmat;
  Kmat << K.fx, 0, K.cx, 0, K.fy, K.cy, 0, 0, 1;
  const Eigen::Matrix3d F21 = Kmat.inverse().transpose() * skew(T21.translation()) * T21.linear() * Kmat.inverse();
  const FeatureGrid grid2(k2.features.points, k2.features.width, k2.features.height);
  std::vector<Candidate> owner(k2.features.points.size());  // best query per keypoint of keyframe 2
  std::vector<int> candidates;
  for (int i = 0; i < static_cast<int>(k1.features.points.size()); ++i) {
    if (k1.point_landmark[i] >= 0) continue;
    const Candidate c = searchPartner(k1, k2, grid2, i, T21, F21, depth, K, config, candidates);
    if (c.index2 >= 0 && c.distance < owner[c.index2].distance) owner[c.index2] = c;
  }
  const Eigen::Vector3d C1 = k1.T_camera_world.inverse().translation(), C2 = k2.T_camera_world.inverse().translation();
  for (const Candidate& c : owner) {
    if (c.index1 < 0) continue;
    const Eigen::Vector2d &x1 = k1.features.points[c.index1], &x2 = k2.features.points[c.index2];
    const Eigen::Vector3d p = triangulateDlt(k1.T_camera_world, normalised(x1, K), k2.T_camera_world, normalised(x2, K));
    if (!p.allFinite() || (p - C1).normalized().dot((p - C2).normalized()) > config.min_parallax_cos) continue;
    if (!reprojectsWell(k1.T_camera_world, p, x1, levelScale(k1.features, c.index1), K, config.chi2_reprojection) ||
        !reprojectsWell(k2.T_camera_world, p, x2, levelScale(k2.features, c.index2), K, config.chi2_reprojection)) {
      continue;
    }
    const int id = map.addPointLandmark(p, k1.features.descriptors.row(c.index1));
    map.addPointObservation(id, keyframe1, c.index1);
    map.addPointObservation(id, keyframe2, c.index2);
    created.push_back(id);
  }
  return created;
}

}  // namespace lvslam::visual
