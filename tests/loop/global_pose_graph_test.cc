// The global pose graph spreads a loop's correction as least squares does
// in closed form, and a false loop edge loses its weight.
#include <cmath>

#include <gtest/gtest.h>

#include "lvslam/loop/global_pose_graph.h"

namespace lvslam::loop {
namespace {

// N poses on a circle of radius 5 m, heading along it.
std::vector<Eigen::Isometry3d> circle(int n) {
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    poses.push_back(makePose(Eigen::Matrix3d(Eigen::AngleAxisd(a + M_PI / 2, Eigen::Vector3d::UnitZ())),
                             Eigen::Vector3d(5.0 * std::cos(a), 5.0 * std::sin(a), 0.0)));
  }
  return poses;
}

GraphEdge between(const std::vector<Eigen::Isometry3d>& truth, int from, int to, const Matrix6d& information,
                  bool robust = false) {
  return {from, to, truth[static_cast<std::size_t>(from)].inverse() * truth[static_cast<std::size_t>(to)],
          information, robust};
}

Matrix6d drift(double sigma_m, double sigma_deg) {
  Vector6d w;
  w << Eigen::Vector3d::Constant(1.0 / (sigma_m * sigma_m)),
      Eigen::Vector3d::Constant(1.0 / std::pow(sigma_deg * M_PI / 180.0, 2));
  return w.asDiagonal();
}

TEST(GlobalPoseGraph, OneLoopEdgeSpreadsTheCorrectionAsTheClosedFormOnACircle) {
  // Odometry rises eps per edge (a vertical drift); the loop edge says the
  // last node is level with the first. A cycle of N equal edges shares the
  // misclosure (N-1) eps equally, so node i ends at z = i eps / N. Rotations
  // are held stiff so that no tilt takes a share of the vertical misclosure.
  const int n = 24;
  const double eps = 0.01;
  const std::vector<Eigen::Isometry3d> truth = circle(n);
  const Matrix6d information = drift(0.03, 1e-4);
  std::vector<GraphEdge> edges;
  std::vector<Eigen::Isometry3d> odometry{truth[0]};
  for (int i = 1; i < n; ++i) {
    GraphEdge edge = between(truth, i - 1, i, information);
    edge.T_from_to.translation().z() += eps;
    edges.push_back(edge);
    odometry.push_back(odometry.back() * edge.T_from_to);
  }
  edges.push_back(between(truth, 0, n - 1, information));
  const GraphSolution solution = solveGlobalPoseGraph(odometry, edges, 3.0);
  ASSERT_TRUE(solution.solved);
  for (int i = 0; i < n; ++i) {
    const Eigen::Isometry3d& T = solution.poses[static_cast<std::size_t>(i)];
    EXPECT_NEAR(T.translation().z(), i * eps / n, 1e-6) << i;
    EXPECT_NEAR((T.translation() - truth[static_cast<std::size_t>(i)].translation()).head<2>().norm(), 0.0, 1e-6) << i;
    EXPECT_NEAR(rotationAngle(truth[static_cast<std::size_t>(i)].inverse() * T), 0.0, 1e-6) << i;
  }
}

TEST(GlobalPoseGraph, AFalseLoopEdgeIsDownWeightedAndDoesNotBendTheMap) {
  const int n = 30;
  const std::vector<Eigen::Isometry3d> truth = circle(n);
  const Matrix6d odometry_information = drift(0.03, 0.3);
  const Matrix6d loop_information = drift(0.05, 0.5);
  std::vector<GraphEdge> edges;
  for (int i = 1; i < n; ++i) edges.push_back(between(truth, i - 1, i, odometry_information));
  edges.push_back(between(truth, 0, n - 1, loop_information, true));
  // A false loop: node 15, across the circle (10 m away), said to be where node 0 is.
  edges.push_back({0, 15, Eigen::Isometry3d::Identity(), loop_information, true});
  const GraphSolution solution = solveGlobalPoseGraph(truth, edges, 3.0);
  ASSERT_TRUE(solution.solved);
  double worst = 0.0;
  for (int i = 0; i < n; ++i)
    worst = std::max(worst, (solution.poses[static_cast<std::size_t>(i)].translation() -
                             truth[static_cast<std::size_t>(i)].translation()).norm());
  EXPECT_LT(worst, 0.01);
  EXPECT_GT(solution.edge_weights[n - 1], 0.9);  // the true loop
  EXPECT_LT(solution.edge_weights[n], 1e-3);     // the false one
  EXPECT_EQ(solution.edge_weights[0], 1.0);      // odometry is not robust
}

}  // namespace
}  // namespace lvslam::loop
