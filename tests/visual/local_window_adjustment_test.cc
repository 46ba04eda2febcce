#include "lvslam/visual/optimize/local_window_adjustment.h"

#include <algorithm>
#include <map>
#include <random>

#include <gtest/gtest.h>

#include "lvslam/visual/geometry/orthonormal_line.h"
#include "visual/synthetic_scene.h"

namespace lvslam::visual {
namespace {

using testing::SyntheticScene;

// A map of the synthetic scene: one keyframe per camera with a keypoint per
// visible point and a segment per visible line, all associated.
struct SceneMap {
  SyntheticScene scene;
  VisualMap map;
  std::vector<int> keyframes, points, lines;
};

SceneMap buildMap(int cameras, unsigned seed) {
  SceneMap m{testing::makeScene(cameras, 120, 20, 0.15, seed), {}, {}, {}, {}};
  const SyntheticScene& s = m.scene;
  for (const auto& p : s.points) m.points.push_back(m.map.addPointLandmark(p, cv::Mat()));
  for (const auto& seg : s.segments) m.lines.push_back(m.map.addLineLandmark(testing::lineOf(seg), seg.a, seg.b, cv::Mat()));
  for (const auto& T : s.T_camera_world) {
    Keyframe kf;
    kf.T_camera_world = T;
    kf.features.pyramid.inv_sigma2 = {1.0};
    std::vector<std::pair<int, int>> point_obs, line_obs;  // (landmark, feature index)
    for (size_t i = 0; i < s.points.size(); ++i) {
      const Eigen::Vector3d uvz = s.project(T, s.points[i]);
      if (!s.visible(uvz)) continue;
      point_obs.emplace_back(m.points[i], static_cast<int>(kf.features.points.size()));
      kf.features.points.push_back(uvz.head<2>());
      kf.features.keypoints.emplace_back(cv::Point2f(uvz.x(), uvz.y()), 31.0f);
      kf.features.keypoints.back().octave = 0;
    }
    for (size_t j = 0; j < s.segments.size(); ++j) {
      const Eigen::Vector3d a = s.project(T, s.segments[j].a), b = s.project(T, s.segments[j].b);
      if (!s.visible(a) || !s.visible(b)) continue;
      line_obs.emplace_back(m.lines[j], static_cast<int>(kf.features.lines.size()));
      LineSegment seg;
      seg.start = a.head<2>();
      seg.end = b.head<2>();
      kf.features.lines.push_back(seg);
    }
    const int id = m.map.addKeyframe(std::move(kf));
    m.keyframes.push_back(id);
    for (const auto& [lm, index] : point_obs) m.map.addPointObservation(lm, id, index);
    for (const auto& [lm, index] : line_obs) m.map.addLineObservation(lm, id, index);
  }
  return m;
}

void perturbMap(SceneMap& m, int first_free_keyframe) {
  std::mt19937 rng(9);
  std::normal_distribution<double> n(0.0, 1.0);
  for (size_t k = first_free_keyframe; k < m.keyframes.size(); ++k) {
    Vector6d xi;
    xi << 0.02 * n(rng), 0.02 * n(rng), 0.02 * n(rng), 0.005 * n(rng), 0.005 * n(rng), 0.005 * n(rng);
    Keyframe& kf = m.map.keyframe(m.keyframes[k]);
    kf.T_camera_world = expSE3(xi) * kf.T_camera_world;
  }
  for (const int p : m.points) m.map.point(p).p_world += 0.03 * Eigen::Vector3d(n(rng), n(rng), n(rng));
  for (const int l : m.lines) {
    auto& line = m.map.line(l).line_world;
    line = OrthonormalLine::fromPlucker(line).plus(Eigen::Vector4d(0.005 * n(rng), 0.005 * n(rng), 0.005 * n(rng), 0.005 * n(rng))).toPlucker();
  }
}

double maxPoseError(const SceneMap& m) {
  double e = 0.0;
  for (size_t k = 0; k < m.keyframes.size(); ++k) {
    const Eigen::Isometry3d& est = m.map.keyframe(m.keyframes[k]).T_camera_world;
    e = std::max(e, (est.inverse().translation() - m.scene.T_camera_world[k].inverse().translation()).norm());
  }
  return e;
}

TEST(LocalWindowAdjustment, WholeMapWindowConvergesToTheTruth) {
  SceneMap m = buildMap(6, 21);
  perturbMap(m, 2);
  ASSERT_GT(maxPoseError(m), 0.01);
  const LocalWindowResult r = adjustLocalWindow(m.map, m.keyframes.back(), m.scene.K);
  ASSERT_TRUE(r.usable);
  EXPECT_EQ(r.fixed_keyframes, 2);
  EXPECT_EQ(r.optimised_keyframes, 4);
  EXPECT_LT(maxPoseError(m), 1e-6);
  for (size_t i = 0; i < m.points.size(); ++i) {
    if (m.map.point(m.points[i]).observations.size() >= 2) {
      EXPECT_LT((m.map.point(m.points[i]).p_world - m.scene.points[i]).norm(), 1e-5);
    }
  }
  EXPECT_EQ(r.removed_point_observations, 0);
}

TEST(LocalWindowAdjustment, SmallWindowFixesOutsideObserversAndRemovesOutliers) {
  SceneMap m = buildMap(6, 22);
  // A gross outlier: one observed keypoint of the last keyframe moved 40 px.
  Keyframe& last = m.map.keyframe(m.keyframes.back());
  int corrupted = -1;
  for (size_t i = 0; i < last.point_landmark.size() && corrupted < 0; ++i) {
    if (last.point_landmark[i] >= 0) corrupted = static_cast<int>(i);
  }
  ASSERT_GE(corrupted, 0);
  const int corrupted_landmark = last.point_landmark[corrupted];
  last.features.points[corrupted] += Eigen::Vector2d(40.0, -30.0);
  LocalWindowConfig config;
  config.window_size = 3;
  const std::vector<int> window = m.map.localWindow(m.keyframes.back(), config.window_size);
  std::map<int, Eigen::Isometry3d> outside;
  for (const int kf : m.keyframes) {
    if (std::find(window.begin(), window.end(), kf) == window.end()) outside[kf] = m.map.keyframe(kf).T_camera_world;
  }
  ASSERT_EQ(outside.size(), 3u);
  const LocalWindowResult r = adjustLocalWindow(m.map, m.keyframes.back(), m.scene.K, config);
  ASSERT_TRUE(r.usable);
  EXPECT_EQ(r.optimised_keyframes, 3);
  EXPECT_EQ(r.fixed_keyframes, 3);  // the other keyframes see the same landmarks
  for (const auto& [kf, T] : outside) EXPECT_TRUE(m.map.keyframe(kf).T_camera_world.isApprox(T, 1e-12));
  EXPECT_GE(r.removed_point_observations, 1);
  EXPECT_EQ(m.map.keyframe(m.keyframes.back()).point_landmark[corrupted], -1);
  for (const Observation& o : m.map.point(corrupted_landmark).observations) {
    EXPECT_NE(o.keyframe, m.keyframes.back());
  }
  // The rest of the window stays at the truth.
  EXPECT_LT(maxPoseError(m), 1e-4);
}

}  // namespace
}  // namespace lvslam::visual
