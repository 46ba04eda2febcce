#pragma once
// A graph of camera poses tied by relative-pose factors, each with its full
// information matrix (possibly singular: a direction a subsystem does not
// observe gets none), solved by Ceres with a Huber kernel. The online
// estimator solves a window of it per frame, the offline refinement all of it.
#include <functional>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/core/se3.h"

namespace lvslam::system {

enum class FactorSource { kLidar, kVisual, kMotion };
const char* factorSourceName(FactorSource source);

// Measures T_from_to = T_world_from^-1 T_world_to; the information is for the
// right perturbation of `to` (the residual log(Z^-1 T_from^-1 T_to), as in
// Ceres' pose_graph_3d example).
struct PoseFactor {
  int from = 0, to = 0;  // node indices
  Eigen::Isometry3d T_from_to = Eigen::Isometry3d::Identity();
  Matrix6d information = Matrix6d::Zero();
  FactorSource source = FactorSource::kMotion;
};

struct PoseNode {
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  bool fixed = false;
};

// The fields a record file (record_file.h) writes and reads back; a field
// added above fails the size check until it is listed here.
template <typename A>
void fields(A& a, PoseFactor& f) {
  static_assert(sizeof(PoseFactor) == 448, "PoseFactor changed: list its fields here");
  a(f.from), a(f.to), a(f.T_from_to), a(f.information), a(f.source);
}
template <typename A>
void fields(A& a, PoseNode& n) {
  static_assert(sizeof(PoseNode) == 144, "PoseNode changed: list its fields here");
  a(n.T_world_camera), a(n.fixed);
}

struct PoseGraphSolveConfig {
  double huber_delta = 3.0;  // on the whitened residual's norm
  int max_iterations = 10;
  bool sparse = false;       // a sparse solver for large (offline) graphs
};

// The factor's residual at the nodes' poses (right tangent at `to`).
Vector6d factorError(const PoseFactor& factor, const std::vector<PoseNode>& nodes);
// e^T Omega e at the nodes' poses.
double factorChiSquare(const PoseFactor& factor, const std::vector<PoseNode>& nodes);

// The covariance of one free node at the solution: the inverse of the
// Gauss-Newton information (J^T J of the whitened, robustified factors) with
// the other free nodes marginalised and the fixed ones held. Translation
// and rotation both in the world frame (t <- t + d_t, R <- exp(d_phi) R),
// the order of a ROS pose covariance.
struct NodeCovariance {
  int node = -1;                     // which node (input)
  std::optional<Matrix6d> covariance;  // none: the node is not free or not observable
};

// Optimises the free nodes in place; returns false (nodes unchanged) when
// the solver failed. A graph without a fixed node is held by its first node.
// With `covariance`, also that node's covariance at the solution.
bool solvePoseGraph(std::vector<PoseNode>& nodes, const std::vector<PoseFactor>& factors,
                    const PoseGraphSolveConfig& config, NodeCovariance* covariance = nullptr);

// A part of a larger graph whose nodes `node(id)` gives: nodes [begin, end)
// free (unless fixed), every other node the factors reach held at its
// current estimate. The factors are solved as one graph (solvePoseGraph,
// the free nodes first, in id order) and the free nodes written back; with
// `covariance`, its node is an id of the larger graph. Returns false (nodes
// unchanged) when the solver failed.
bool solveSubgraph(int begin, int end, const std::vector<const PoseFactor*>& factors,
                   const std::function<PoseNode&(int)>& node, const PoseGraphSolveConfig& config,
                   NodeCovariance* covariance = nullptr);

}  // namespace lvslam::system
