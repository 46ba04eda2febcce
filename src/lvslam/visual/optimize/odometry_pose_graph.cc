#include "lvslam/visual/optimize/odometry_pose_graph.h"

#include <cmath>
#include <string>

#include <ceres/autodiff_cost_function.h>
#include <ceres/loss_function.h>
#include <ceres/manifold.h>
#include <ceres/problem.h>
#include <ceres/product_manifold.h>
#include <ceres/solver.h>

#include "lvslam/core/error.h"
#include "lvslam/visual/residuals/pose_block.h"

namespace lvslam::visual {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

// Relative pose error as in Ceres' pose_graph_3d example, on T_camera_world
// blocks [t, q]: T_a_b = T_a_w T_b_w^-1 against the measurement, translation
// in frame a, rotation as twice the vector part of the error quaternion.
struct RelativePoseError {
  RelativePoseError(const Eigen::Isometry3d& T_a_b, double inv_sigma_t, double inv_sigma_r)
      : t_ab(T_a_b.translation()), q_ba(Eigen::Quaterniond(T_a_b.linear()).conjugate()),
        inv_sigma_t(inv_sigma_t), inv_sigma_r(inv_sigma_r) {}

  template <typename T>
  bool operator()(const T* a, const T* b, T* residual) const {
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> t_a(a), t_b(b);
    const Eigen::Map<const Eigen::Quaternion<T>> q_a(a + 3), q_b(b + 3);
    const Eigen::Quaternion<T> q_ab = q_a * q_b.conjugate();
    const Eigen::Matrix<T, 3, 1> t_ab_est = t_a - q_ab * t_b;
    const Eigen::Quaternion<T> dq = q_ba.cast<T>() * q_ab;
    Eigen::Map<Eigen::Matrix<T, 6, 1>> r(residual);
    r.template head<3>() = (t_ab_est - t_ab.cast<T>()) * T(inv_sigma_t);
    r.template tail<3>() = dq.vec() * T(2.0 * inv_sigma_r);
    return true;
  }

  Eigen::Vector3d t_ab;
  Eigen::Quaterniond q_ba;
  double inv_sigma_t, inv_sigma_r;
};

// Absolute prior: camera centre c = -R^T t against the prior's, rotation
// error R R_p^T (same terms as residuals/pose_prior.h, for autodiff).
struct PriorPoseError {
  PriorPoseError(const Eigen::Isometry3d& prior_T_camera_world, double inv_sigma_t, double inv_sigma_r)
      : c_p(-prior_T_camera_world.linear().transpose() * prior_T_camera_world.translation()),
        q_p_inv(Eigen::Quaterniond(prior_T_camera_world.linear()).conjugate()),
        inv_sigma_t(inv_sigma_t), inv_sigma_r(inv_sigma_r) {}

  template <typename T>
  bool operator()(const T* x, T* residual) const {
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> t(x);
    const Eigen::Map<const Eigen::Quaternion<T>> q(x + 3);
    const Eigen::Matrix<T, 3, 1> c = -(q.conjugate() * t);
    const Eigen::Quaternion<T> dq = q * q_p_inv.cast<T>();
    Eigen::Map<Eigen::Matrix<T, 6, 1>> r(residual);
    r.template head<3>() = (c - c_p.cast<T>()) * T(inv_sigma_t);
    r.template tail<3>() = dq.vec() * T(2.0 * inv_sigma_r);
    return true;
  }

  Eigen::Vector3d c_p;
  Eigen::Quaterniond q_p_inv;
  double inv_sigma_t, inv_sigma_r;
};

using PoseManifold = ceres::ProductManifold<ceres::EuclideanManifold<3>, ceres::EigenQuaternionManifold>;

}  // namespace

PoseGraphResult optimizePoseGraph(std::vector<PoseGraphNode>& nodes, const std::vector<PoseGraphEdge>& edges,
                                  const PoseGraphConfig& config) {
  PoseGraphResult result;
  const int n = static_cast<int>(nodes.size());
  for (const PoseGraphEdge& e : edges) {
    if (e.a < 0 || e.a >= n || e.b < 0 || e.b >= n || e.a == e.b)
      throw Error("optimizePoseGraph", "edge (" + std::to_string(e.a) + ", " + std::to_string(e.b) +
                                           ") is not between two of the " + std::to_string(n) + " nodes");
  }
  bool any_fixed = false;
  for (const PoseGraphNode& node : nodes) {
    result.priors += node.prior_T_camera_world.has_value() && !node.fixed;
    any_fixed = any_fixed || node.fixed;
  }
  if (result.priors == 0 && !any_fixed) return result;  // nothing fixes the gauge

  std::vector<PoseBlock> blocks(nodes.size());
  for (int i = 0; i < n; ++i) blocks[i] = toPoseBlock(nodes[i].T_camera_world);

  ceres::Problem::Options problem_options;
  problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  PoseManifold manifold;
  const double edge_t = 1.0 / config.edge_sigma_m, edge_r = 1.0 / (config.edge_sigma_deg * kDegToRad);
  const double prior_t = 1.0 / config.prior_sigma_m, prior_r = 1.0 / (config.prior_sigma_deg * kDegToRad);
  for (const PoseGraphEdge& e : edges) {
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<RelativePoseError, 6, 7, 7>(
                                 new RelativePoseError(e.T_a_b, edge_t, edge_r)),
                             nullptr, blocks[e.a].data(), blocks[e.b].data());
    ++result.edges;
  }
  for (int i = 0; i < n; ++i) {
    if (!nodes[i].prior_T_camera_world || nodes[i].fixed) continue;  // a fixed node's prior changes nothing
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<PriorPoseError, 6, 7>(
                                 new PriorPoseError(*nodes[i].prior_T_camera_world, prior_t, prior_r)),
                             new ceres::HuberLoss(config.prior_huber_delta), blocks[i].data());
  }
  for (int i = 0; i < n; ++i)
    if (problem.HasParameterBlock(blocks[i].data())) {
      problem.SetManifold(blocks[i].data(), &manifold);
      if (nodes[i].fixed) problem.SetParameterBlockConstant(blocks[i].data());
    }

  ceres::Solver::Options options;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  options.sparse_linear_algebra_library_type = ceres::EIGEN_SPARSE;
  options.max_num_iterations = config.max_iterations;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  result.iterations = static_cast<int>(summary.iterations.size());
  result.initial_cost = summary.initial_cost;
  result.final_cost = summary.final_cost;
  if (!summary.IsSolutionUsable()) return result;
  for (int i = 0; i < n; ++i)
    if (!nodes[i].fixed) nodes[i].T_camera_world = fromPoseBlock(blocks[i].data());
  result.solved = true;
  return result;
}

}  // namespace lvslam::visual
