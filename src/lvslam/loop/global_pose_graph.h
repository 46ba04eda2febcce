#pragma once
// The global pose graph over LiDAR keyframes, solved by Ceres: odometry
// edges between consecutive keyframes (plain least squares) and loop edges
// from verification behind a Cauchy kernel, so that a loop the rest of the
// graph contradicts loses its weight instead of bending the map.
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/core/se3.h"

namespace lvslam::loop {

// Measures T_from_to = T_odom_from^-1 T_odom_to; the information is for a
// right perturbation of `to` in the (rho, phi) order.
struct GraphEdge {
  int from = 0, to = 0;
  Eigen::Isometry3d T_from_to = Eigen::Isometry3d::Identity();
  Matrix6d information = Matrix6d::Identity();
  bool robust = false;  // a loop edge: Cauchy kernel
};

struct GraphSolution {
  std::vector<Eigen::Isometry3d> poses;  // one per node, the first held where it was
  // Per edge, the kernel's weight at the solution (1 for plain edges):
  // rho'(s) = 1 / (1 + s / k^2), s the whitened squared residual.
  std::vector<double> edge_weights;
  bool solved = false;
};

// kernel: the Cauchy scale k on the whitened residual's norm.
GraphSolution solveGlobalPoseGraph(const std::vector<Eigen::Isometry3d>& initial, const std::vector<GraphEdge>& edges,
                                   double kernel);

// Whitened squared residual of an edge at the given poses.
double edgeChiSquare(const GraphEdge& edge, const std::vector<Eigen::Isometry3d>& poses);

}  // namespace lvslam::loop
