#pragma once
// Pose graph over keyframes with the LiDAR odometry as anchors (lvslam's
// addition, docs/visual-subsystem.md "LiDAR pose priors"): relative poses
// between keyframes, taken from the visual map as it stands, keep its local
// shape; absolute priors from the LiDAR odometry remove its drift. Plain data
// in and out; Ceres lives only in the .cc.
#include <optional>
#include <vector>

#include <Eigen/Geometry>

namespace lvslam::visual {

struct PoseGraphNode {
  Eigen::Isometry3d T_camera_world = Eigen::Isometry3d::Identity();
  std::optional<Eigen::Isometry3d> prior_T_camera_world;  // from the LiDAR odometry
  bool fixed = false;  // enters its edges as it stands, is not optimised
};

// Edge a -> b (indices into the nodes) measuring T_a_b = T_a_world * T_b_world^-1.
struct PoseGraphEdge {
  int a = 0, b = 0;
  Eigen::Isometry3d T_a_b = Eigen::Isometry3d::Identity();
};

struct PoseGraphConfig {
  double edge_sigma_m = 0.005;    // of an edge's translation (in frame a)
  double edge_sigma_deg = 0.1;    // of its rotation
  double prior_sigma_m = 0.01;    // of a prior's camera centre
  double prior_sigma_deg = 0.2;   // of its rotation
  double prior_huber_delta = 3.548519;  // sqrt(12.592): chi2 with 6 DoF at 95 %
  int max_iterations = 10;
};

struct PoseGraphResult {
  bool solved = false;  // false: no prior nor fixed node (no gauge) or the solver failed; poses unchanged
  int priors = 0, edges = 0, iterations = 0;
  double initial_cost = 0.0, final_cost = 0.0;
};

// Optimises the nodes' T_camera_world in place. Nodes that no edge or prior
// reaches keep their pose. Throws lvslam::Error on an edge index out of range.
PoseGraphResult optimizePoseGraph(std::vector<PoseGraphNode>& nodes, const std::vector<PoseGraphEdge>& edges,
                                  const PoseGraphConfig& config);

}  // namespace lvslam::visual
