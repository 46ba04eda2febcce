#include <gtest/gtest.h>

#include "lvslam/visual/tracking/frame_tracker.h"
#include "visual/synthetic_scene.h"

namespace lvslam::visual {
namespace {

using testing::SyntheticScene;

// A map holding the scene's points and segments as landmarks, each moved by
// G_new_old (a map that local BA or the map correction moved as a whole).
struct SceneMap {
  VisualMap map;
  std::vector<int> points, lines;
};

SceneMap mapOf(const SyntheticScene& s, const Eigen::Isometry3d& G_new_old) {
  SceneMap m;
  for (const auto& p : s.points) m.points.push_back(m.map.addPointLandmark(G_new_old * p, cv::Mat()));
  for (const auto& seg : s.segments)
    m.lines.push_back(m.map.addLineLandmark(PluckerLine::fromPoints(G_new_old * seg.a, G_new_old * seg.b),
                                            G_new_old * seg.a, G_new_old * seg.b, cv::Mat()));
  return m;
}

// What a frame at T_camera_world measured of the scene, exactly.
TrackedObservations observe(const SyntheticScene& s, const SceneMap& m, const Eigen::Isometry3d& T_camera_world) {
  TrackedObservations o;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Eigen::Vector3d uvz = s.project(T_camera_world, s.points[i]);
    if (s.visible(uvz)) o.points.push_back({m.points[i], uvz.head<2>().cast<float>(), 1.0f});
  }
  for (std::size_t i = 0; i < s.segments.size(); ++i) {
    const Eigen::Vector3d a = s.project(T_camera_world, s.segments[i].a + 0.2 * (s.segments[i].b - s.segments[i].a));
    const Eigen::Vector3d b = s.project(T_camera_world, s.segments[i].a + 0.7 * (s.segments[i].b - s.segments[i].a));
    if (s.visible(a) && s.visible(b))
      o.lines.push_back({m.lines[i], a.head<2>().cast<float>(), b.head<2>().cast<float>()});
  }
  return o;
}

Eigen::Isometry3d perturbed(const Eigen::Isometry3d& T) {
  return expSE3((Vector6d() << 0.03, -0.02, 0.04, 0.01, -0.015, 0.008).finished()) * T;
}

double centreError(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.inverse().translation() - b.inverse().translation()).norm();
}

// Landmarks moved after the frame was tracked: the frame's pose follows them
// exactly (pixels are stored as float, hence 1e-5).
TEST(RelocateInMap, FollowsLandmarksThatMovedAfterTracking) {
  const SyntheticScene s = testing::makeScene(3, 150, 20, 0.2, 21);
  const Eigen::Isometry3d T = s.T_camera_world[1];
  const Eigen::Isometry3d G = expSE3((Vector6d() << 0.05, 0.02, -0.03, 0.01, 0.02, -0.01).finished());
  const SceneMap before = mapOf(s, Eigen::Isometry3d::Identity());
  const TrackedObservations o = observe(s, before, T);
  ASSERT_GT(o.points.size(), 50u);
  ASSERT_GT(o.lines.size(), 5u);
  const SceneMap after = mapOf(s, G);
  const FrameTrackerConfig config;

  const auto T_same = relocateInMap(before.map, o, perturbed(T), s.K, config);
  ASSERT_TRUE(T_same);
  EXPECT_LT(centreError(*T_same, T), 1e-5);
  const auto T_moved = relocateInMap(after.map, o, T, s.K, config);
  ASSERT_TRUE(T_moved);
  const Eigen::Isometry3d expected = T * G.inverse();
  EXPECT_LT(centreError(*T_moved, expected), 1e-5);
  EXPECT_LT(rotationAngle(*T_moved * expected.inverse()), 1e-6);
}

// Landmarks culled or merged since are gone from the map (here moved 1 cm
// first, too little for the chi2 test to reject them, had they stayed): the
// frame's observations of them are skipped; with too few left the frame is
// not moved.
TEST(RelocateInMap, SkipsRemovedLandmarksAndNeedsEnoughInliers) {
  const SyntheticScene s = testing::makeScene(3, 150, 0, 0.2, 22);
  const Eigen::Isometry3d T = s.T_camera_world[2];
  SceneMap m = mapOf(s, Eigen::Isometry3d::Identity());
  const TrackedObservations o = observe(s, m, T);
  ASSERT_GT(o.points.size(), 60u);
  for (std::size_t i = 0; i < o.points.size(); i += 2) {
    m.map.point(o.points[i].landmark).p_world += Eigen::Vector3d(0.01, 0.0, 0.0);
    m.map.removePoint(o.points[i].landmark);
  }
  const FrameTrackerConfig config;
  const auto T_kept = relocateInMap(m.map, o, perturbed(T), s.K, config);
  ASSERT_TRUE(T_kept);
  EXPECT_LT(centreError(*T_kept, T), 1e-5);

  for (std::size_t i = 1; i < o.points.size(); i += 2)
    if (i > 2 * static_cast<std::size_t>(config.min_inliers) - 4) m.map.removePoint(o.points[i].landmark);
  EXPECT_FALSE(relocateInMap(m.map, o, perturbed(T), s.K, config));
}

// The tracker's inliers become observations: landmark, undistorted pixel and
// the keypoint's pyramid weight; unmatched features are left out.
TEST(TrackedObservations, KeepTheInliersWithTheirWeights) {
  TrackedFrame frame;
  frame.features.points = {{10.0, 20.0}, {30.0, 40.0}, {50.0, 60.0}};
  frame.features.keypoints.resize(3);
  frame.features.keypoints[2].octave = 2;
  frame.features.pyramid.inv_sigma2 = {1.0, 1.0 / 1.44, 1.0 / 2.0736};
  frame.features.lines.resize(2);
  frame.features.lines[1].start = {1.0, 2.0};
  frame.features.lines[1].end = {3.0, 4.0};
  frame.point_landmark = {7, -1, 9};
  frame.line_landmark = {-1, 4};
  const TrackedObservations o = trackedObservations(frame);
  ASSERT_EQ(o.points.size(), 2u);
  EXPECT_EQ(o.points[0].landmark, 7);
  EXPECT_EQ(o.points[1].landmark, 9);
  EXPECT_EQ(o.points[1].pixel, Eigen::Vector2f(50.0f, 60.0f));
  EXPECT_FLOAT_EQ(o.points[0].inv_sigma2, 1.0f);
  EXPECT_FLOAT_EQ(o.points[1].inv_sigma2, static_cast<float>(1.0 / 2.0736));
  ASSERT_EQ(o.lines.size(), 1u);
  EXPECT_EQ(o.lines[0].landmark, 4);
  EXPECT_EQ(o.lines[0].end, Eigen::Vector2f(3.0f, 4.0f));
}

}  // namespace
}  // namespace lvslam::visual
