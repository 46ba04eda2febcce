#include "lvslam/visual/module/odometry_map_correction.h"
#include "lvslam/visual/optimize/odometry_pose_graph.h"

#include <gtest/gtest.h>

#include "lvslam/core/error.h"
#include "lvslam/core/se3.h"

namespace lvslam::visual {
namespace {

// T_camera_world of a camera driving along a curve, 0.3 m and 3 deg per step.
Eigen::Isometry3d trueCamera(int i) {
  Vector6d xi;
  xi << 0.0, 0.0, 0.3, 0.0, 3.0 * M_PI / 180.0, 0.0;
  return (makePose(expSO3(Eigen::Vector3d(0.1, -0.2, 0.05)), Eigen::Vector3d(1, 2, 0)) * expSE3(i * xi)).inverse();
}

// A drift that grows along the path: world-side, 2 mm and 0.1 deg per step.
Eigen::Isometry3d drift(int i) {
  Vector6d xi;
  xi << 0.002, -0.001, 0.001, 0.0005, 0.0017, -0.0008;
  return expSE3(i * xi);
}

double translationError(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.inverse().translation() - b.inverse().translation()).norm();
}

TEST(OdometryPoseGraph, ExactEdgesAndSomePriorsRemoveTheDrift) {
  const int n = 20;
  std::vector<PoseGraphNode> nodes(n);
  std::vector<PoseGraphEdge> edges;
  for (int i = 0; i < n; ++i) {
    nodes[i].T_camera_world = trueCamera(i) * drift(i).inverse();
    if (i % 4 == 0) nodes[i].prior_T_camera_world = trueCamera(i);
    if (i > 0) edges.push_back({i - 1, i, trueCamera(i - 1) * trueCamera(i).inverse()});
    if (i > 2) edges.push_back({i - 3, i, trueCamera(i - 3) * trueCamera(i).inverse()});
  }
  ASSERT_GT(translationError(nodes.back().T_camera_world, trueCamera(n - 1)), 0.05);  // the drift is there
  PoseGraphConfig config;
  config.max_iterations = 50;
  const PoseGraphResult r = optimizePoseGraph(nodes, edges, config);
  ASSERT_TRUE(r.solved);
  EXPECT_EQ(r.priors, 5);
  EXPECT_EQ(r.edges, static_cast<int>(edges.size()));
  // Every measurement agrees with the truth: the optimum is the truth, the
  // nodes without a prior included.
  for (int i = 0; i < n; ++i) {
    EXPECT_LT(translationError(nodes[i].T_camera_world, trueCamera(i)), 1e-6) << i;
    EXPECT_LT(rotationAngle(nodes[i].T_camera_world * trueCamera(i).inverse()), 1e-7) << i;
  }
  EXPECT_LT(r.final_cost, 1e-10);
}

TEST(OdometryPoseGraph, WithoutAPriorNothingMovesAndBadEdgesAreErrors) {
  std::vector<PoseGraphNode> nodes(3);
  for (int i = 0; i < 3; ++i) nodes[i].T_camera_world = trueCamera(i) * drift(i);
  const std::vector<PoseGraphEdge> edges{{0, 1, trueCamera(0) * trueCamera(1).inverse()}};
  const PoseGraphResult r = optimizePoseGraph(nodes, edges, {});
  EXPECT_FALSE(r.solved);
  EXPECT_TRUE(nodes[1].T_camera_world.isApprox(trueCamera(1) * drift(1), 1e-15));
  EXPECT_THROW(optimizePoseGraph(nodes, {{0, 3, Eigen::Isometry3d::Identity()}}, {}), Error);
  EXPECT_THROW(optimizePoseGraph(nodes, {{1, 1, Eigen::Isometry3d::Identity()}}, {}), Error);
}

TEST(OdometryPoseGraph, FixedNodesHoldStillAndFixTheGauge) {
  const int n = 8;
  std::vector<PoseGraphNode> nodes(n);
  std::vector<PoseGraphEdge> edges;
  for (int i = 0; i < n; ++i) {
    nodes[i].T_camera_world = trueCamera(i) * drift(i).inverse();
    if (i > 0) edges.push_back({i - 1, i, trueCamera(i - 1) * trueCamera(i).inverse()});
  }
  // Nodes 0 and 5 are held at the truth and no free node has a prior: the
  // held nodes alone fix the gauge, and the exact edges bring the free ones
  // (between them and past them) to the truth.
  for (const int held : {0, 5}) {
    nodes[held].T_camera_world = trueCamera(held);
    nodes[held].fixed = true;
  }
  nodes[5].prior_T_camera_world = trueCamera(5) * drift(5);  // a held node's prior changes nothing
  ASSERT_GT(translationError(nodes[7].T_camera_world, trueCamera(7)), 0.01);
  PoseGraphConfig config;
  config.max_iterations = 50;
  const PoseGraphResult r = optimizePoseGraph(nodes, edges, config);
  ASSERT_TRUE(r.solved);
  EXPECT_EQ(r.priors, 0);
  EXPECT_TRUE(nodes[0].T_camera_world.isApprox(trueCamera(0), 0.0));
  EXPECT_TRUE(nodes[5].T_camera_world.isApprox(trueCamera(5), 0.0));
  for (int i = 1; i < n; ++i) {
    EXPECT_LT(translationError(nodes[i].T_camera_world, trueCamera(i)), 1e-6) << i;
    EXPECT_LT(rotationAngle(nodes[i].T_camera_world * trueCamera(i).inverse()), 1e-7) << i;
  }
}

// A map of n keyframes in which every keyframe from `first_jumped` on, and
// the point each created, jumped by G; odometry poses that know the truth
// (in another world frame); each keyframe's point is seen by the next one.
struct JumpedMap {
  VisualMap map;
  std::vector<int> keyframes, points;
  std::vector<Eigen::Vector3d> p_true;
};

JumpedMap jumpedMap(int n, int first_jumped, const Eigen::Isometry3d& G) {
  JumpedMap m;
  for (int i = 0; i < n; ++i) {
    Keyframe k;
    k.timestamp = i;
    k.features.keypoints.resize(2);
    k.features.lines.resize(1);
    k.T_camera_world = i < first_jumped ? trueCamera(i) : trueCamera(i) * G.inverse();
    m.keyframes.push_back(m.map.addKeyframe(k));
  }
  for (int i = 0; i < n; ++i) {
    // A point 4 m in front of keyframe i, created by it and seen by the next.
    const Eigen::Vector3d p = trueCamera(i).inverse() * Eigen::Vector3d(0.3, -0.1, 4.0);
    m.p_true.push_back(p);
    const int id = m.map.addPointLandmark(i < first_jumped ? p : G * p, cv::Mat());
    m.map.addPointObservation(id, m.keyframes[i], 0);
    if (i + 1 < n) m.map.addPointObservation(id, m.keyframes[i + 1], 1);
    m.points.push_back(id);
  }
  // The odometry's world is elsewhere; its poses are the truth there.
  const Eigen::Isometry3d T_odom_world = expSE3((Vector6d() << 3, -1, 0.5, 0.0, 0.0, 0.7).finished());
  for (int i = 0; i < n; ++i) m.map.setOdometryPose(m.keyframes[i], T_odom_world * trueCamera(i).inverse());
  return m;
}

// The odometry is believed, the map's jump is not.
MapCorrectionConfig believeTheOdometry(int window_keyframes) {
  MapCorrectionConfig config;
  config.window_keyframes = window_keyframes;
  config.graph.prior_sigma_m = 0.001;
  config.graph.prior_sigma_deg = 0.01;
  config.graph.edge_sigma_m = 1.0;
  config.graph.edge_sigma_deg = 30.0;
  config.graph.max_iterations = 50;
  return config;
}

// The second half of the map jumped: the whole-map correction puts
// keyframes, points and lines back.
TEST(OdometryMapCorrection, KeyframesAndTheirLandmarksReturnToTheOdometry) {
  const Eigen::Isometry3d G = expSE3((Vector6d() << 0.05, -0.03, 0.02, 0.01, -0.02, 0.015).finished());
  const int n = 6;
  JumpedMap m = jumpedMap(n, 3, G);
  VisualMap& map = m.map;
  const Eigen::Vector3d a = trueCamera(4).inverse() * Eigen::Vector3d(-1, 0, 5);
  const Eigen::Vector3d b = trueCamera(4).inverse() * Eigen::Vector3d(1, 0.5, 5);
  const int line = map.addLineLandmark(PluckerLine::fromPoints(G * a, G * b), G * a, G * b, cv::Mat());
  map.addLineObservation(line, m.keyframes[4], 0);
  map.setFusionDirection(line, G.linear() * (b - a));

  const MapCorrectionResult r = correctMapWithOdometry(map, believeTheOdometry(0));
  ASSERT_TRUE(r.graph.solved);
  EXPECT_EQ(r.keyframes, n);
  EXPECT_EQ(r.held_keyframes, 0);
  EXPECT_EQ(r.graph.priors, n);
  EXPECT_GT(r.max_shift_m, 0.03);
  for (int i = 0; i < n; ++i)
    EXPECT_LT(translationError(map.keyframe(m.keyframes[i]).T_camera_world, trueCamera(i)), 1e-4) << i;
  for (int i = 0; i < n; ++i) EXPECT_LT((map.point(m.points[i]).p_world - m.p_true[i]).norm(), 1e-3) << i;
  const LineLandmark& l = map.line(line);
  EXPECT_LT((l.start_world - a).norm(), 1e-3);
  EXPECT_LT((l.end_world - b).norm(), 1e-3);
  EXPECT_LT(l.line_world.distanceTo(a), 1e-3);
  EXPECT_LT(l.line_world.distanceTo(b), 1e-3);
  EXPECT_GT(l.fusion_direction->dot((b - a).normalized()), std::cos(1e-3));
}

// With a window, the keyframes older than it and the points they created
// stay exactly where they are, even when they are wrong (they were
// corrected while they were new); the window returns to the odometry.
TEST(OdometryMapCorrection, AWindowCorrectsTheNewestKeyframesAndHoldsTheRest) {
  const Eigen::Isometry3d G = expSE3((Vector6d() << 0.05, -0.03, 0.02, 0.01, -0.02, 0.015).finished());
  const int n = 12, window = 4;
  JumpedMap m = jumpedMap(n, 1, G);  // the old part jumped too (keyframe 0 aligns the odometry)
  VisualMap& map = m.map;
  std::vector<Eigen::Isometry3d> before;
  std::vector<Eigen::Vector3d> points_before;
  for (int i = 0; i < n; ++i) {
    before.push_back(map.keyframe(m.keyframes[i]).T_camera_world);
    points_before.push_back(map.point(m.points[i]).p_world);
  }
  const MapCorrectionResult r = correctMapWithOdometry(map, believeTheOdometry(window));
  ASSERT_TRUE(r.graph.solved);
  EXPECT_EQ(r.keyframes, window);
  EXPECT_EQ(r.held_keyframes, 1);  // the predecessor (no covisibility in this map)
  EXPECT_EQ(r.graph.priors, window);
  EXPECT_EQ(r.T_new_old.size(), static_cast<size_t>(window));
  for (int i = 0; i < n - window; ++i) {
    EXPECT_TRUE(map.keyframe(m.keyframes[i]).T_camera_world.isApprox(before[i], 0.0)) << i;
    EXPECT_EQ(map.point(m.points[i]).p_world, points_before[i]) << i;
  }
  // The loose edge to the held predecessor gives way to the tight priors.
  for (int i = n - window; i < n; ++i) {
    EXPECT_LT(translationError(map.keyframe(m.keyframes[i]).T_camera_world, trueCamera(i)), 1e-3) << i;
    EXPECT_LT((map.point(m.points[i]).p_world - m.p_true[i]).norm(), 1e-2) << i;
  }
}

}  // namespace
}  // namespace lvslam::visual
