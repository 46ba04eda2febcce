#include "lvslam/system/online/pose_graph.h"

#include <algorithm>
#include <array>
#include <map>
#include <memory>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <ceres/crs_matrix.h>
#include <ceres/loss_function.h>
#include <ceres/manifold.h>
#include <ceres/problem.h>
#include <ceres/product_manifold.h>
#include <ceres/solver.h>

#include "lvslam/system/online/relative_pose_cost.h"
#include "lvslam/system/online/pose_information.h"

namespace lvslam::system {

namespace {

// Square root of a positive semi-definite information: L^T L = Omega.
Matrix6d squareRoot(const Matrix6d& information) {
  const Eigen::SelfAdjointEigenSolver<Matrix6d> solver(0.5 * (information + information.transpose()));
  const Vector6d lambda = solver.eigenvalues().cwiseMax(0.0);
  return lambda.cwiseSqrt().asDiagonal() * solver.eigenvectors().transpose();
}

// Parameter blocks [t_world_camera (3), q_world_camera (x, y, z, w)].
using Block = std::array<double, 7>;
using PoseManifold = ceres::ProductManifold<ceres::EuclideanManifold<3>, ceres::EigenQuaternionManifold>;

Block toBlock(const Eigen::Isometry3d& T) {
  const Eigen::Quaterniond q(T.linear());
  return {T.translation().x(), T.translation().y(), T.translation().z(), q.x(), q.y(), q.z(), q.w()};
}

Eigen::Isometry3d fromBlock(const Block& b) {
  return makePose(Eigen::Quaterniond(b[6], b[3], b[4], b[5]).normalized(), Eigen::Vector3d(b[0], b[1], b[2]));
}

// The 6x6 block of (J^T J)^-1 of `target` over the problem's free blocks,
// in the world frame: the manifold's tangent is the translation, then the
// quaternion's left update, whose delta is half the rotation angle (Ceres:
// q <- [cos|d|, sin|d| d/|d|] q), so rotation rows scale by 2. A direction no factor reaches (a LiDAR
// odometry frame along its degenerate axis) gets a tiny floor so the
// factorisation stands; it does not couple to the target.
std::optional<Matrix6d> marginalCovariance(ceres::Problem& problem, std::vector<Block>& blocks, std::size_t target) {
  std::vector<double*> free;
  int column = -1;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    double* block = blocks[i].data();
    if (!problem.HasParameterBlock(block) || problem.IsParameterBlockConstant(block)) continue;
    if (i == target) column = 6 * static_cast<int>(free.size());
    free.push_back(block);
  }
  if (column < 0) return std::nullopt;
  ceres::Problem::EvaluateOptions options;
  options.parameter_blocks = free;
  ceres::CRSMatrix crs;
  if (!problem.Evaluate(options, nullptr, nullptr, nullptr, &crs)) return std::nullopt;
  if (crs.num_cols != 6 * static_cast<int>(free.size())) return std::nullopt;
  const Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor, int>> J(
      crs.num_rows, crs.num_cols, static_cast<int>(crs.values.size()), crs.rows.data(), crs.cols.data(),
      crs.values.data());
  Eigen::SparseMatrix<double> H = Eigen::SparseMatrix<double>(J.transpose()) * J;
  const double floor = 1e-12 * std::max(1.0, H.diagonal().maxCoeff());
  for (int k = 0; k < H.cols(); ++k) H.coeffRef(k, k) += floor;
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(H);
  if (solver.info() != Eigen::Success) return std::nullopt;
  Eigen::MatrixXd unit = Eigen::MatrixXd::Zero(H.cols(), 6);
  unit.block<6, 6>(column, 0).setIdentity();
  const Eigen::MatrixXd x = solver.solve(unit);
  Vector6d to_angle;
  to_angle << 1.0, 1.0, 1.0, 2.0, 2.0, 2.0;
  Matrix6d covariance = to_angle.asDiagonal() * x.block<6, 6>(column, 0) * to_angle.asDiagonal();
  covariance = 0.5 * (covariance + covariance.transpose());
  if (!covariance.allFinite()) return std::nullopt;
  return covariance;
}

}  // namespace

const char* factorSourceName(FactorSource source) {
  switch (source) {
    case FactorSource::kLidar: return "lidar";
    case FactorSource::kVisual: return "visual";
    case FactorSource::kMotion: break;
  }
  return "motion";
}

Vector6d factorError(const PoseFactor& factor, const std::vector<PoseNode>& nodes) {
  const Eigen::Isometry3d T_from_to =
      nodes[static_cast<std::size_t>(factor.from)].T_world_camera.inverse() *
      nodes[static_cast<std::size_t>(factor.to)].T_world_camera;
  return poseDifference(factor.T_from_to, T_from_to);
}

double factorChiSquare(const PoseFactor& factor, const std::vector<PoseNode>& nodes) {
  const Vector6d e = factorError(factor, nodes);
  return e.dot(factor.information * e);
}

bool solvePoseGraph(std::vector<PoseNode>& nodes, const std::vector<PoseFactor>& factors,
                    const PoseGraphSolveConfig& config, NodeCovariance* covariance) {
  if (nodes.empty() || factors.empty()) return true;
  std::vector<Block> blocks;
  blocks.reserve(nodes.size());
  for (const PoseNode& node : nodes) blocks.push_back(toBlock(node.T_world_camera));
  ceres::Problem problem;
  for (const PoseFactor& f : factors) {
    auto* cost = new RelativePoseCost(f.T_from_to, squareRoot(f.information));
    problem.AddResidualBlock(cost, new ceres::HuberLoss(config.huber_delta),
                             blocks[static_cast<std::size_t>(f.from)].data(),
                             blocks[static_cast<std::size_t>(f.to)].data());
  }
  bool any_fixed = false;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    double* block = blocks[i].data();
    if (!problem.HasParameterBlock(block)) continue;
    problem.SetManifold(block, new PoseManifold);
    if (nodes[i].fixed) {
      problem.SetParameterBlockConstant(block);
      any_fixed = true;
    }
  }
  if (!any_fixed) {
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (problem.HasParameterBlock(blocks[i].data())) {
        problem.SetParameterBlockConstant(blocks[i].data());
        break;
      }
  }
  ceres::Solver::Options options;
  options.linear_solver_type = config.sparse ? ceres::SPARSE_NORMAL_CHOLESKY : ceres::DENSE_NORMAL_CHOLESKY;
  options.max_num_iterations = config.max_iterations;
  // Small problems: run to the minimum, not to Ceres' default 1e-6 relative change.
  options.function_tolerance = 1e-12;
  options.gradient_tolerance = 1e-14;
  options.parameter_tolerance = 1e-12;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  if (!summary.IsSolutionUsable()) return false;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (!nodes[i].fixed) nodes[i].T_world_camera = fromBlock(blocks[i]);
  if (covariance && covariance->node >= 0 && static_cast<std::size_t>(covariance->node) < blocks.size())
    covariance->covariance = marginalCovariance(problem, blocks, static_cast<std::size_t>(covariance->node));
  return true;
}

bool solveSubgraph(int begin, int end, const std::vector<const PoseFactor*>& factors,
                   const std::function<PoseNode&(int)>& node, const PoseGraphSolveConfig& config,
                   NodeCovariance* covariance) {
  std::map<int, int> local;  // id in the larger graph -> index here
  std::vector<PoseNode> nodes;
  const auto localIndex = [&](int id) {
    const auto [it, inserted] = local.try_emplace(id, static_cast<int>(nodes.size()));
    if (inserted) {
      const PoseNode& held = node(id);
      nodes.push_back({held.T_world_camera, held.fixed || id < begin || id >= end});
    }
    return it->second;
  };
  for (int id = begin; id < end; ++id) localIndex(id);
  std::vector<PoseFactor> local_factors;
  local_factors.reserve(factors.size());
  for (const PoseFactor* f : factors) {
    PoseFactor factor = *f;
    factor.from = localIndex(factor.from);
    factor.to = localIndex(factor.to);
    local_factors.push_back(std::move(factor));
  }
  NodeCovariance local_covariance;
  if (covariance)
    if (const auto found = local.find(covariance->node); found != local.end()) local_covariance.node = found->second;
  if (!solvePoseGraph(nodes, local_factors, config, covariance ? &local_covariance : nullptr)) return false;
  for (const auto& [id, index] : local)
    if (id >= begin && id < end) node(id) = nodes[static_cast<std::size_t>(index)];
  if (covariance) covariance->covariance = local_covariance.covariance;
  return true;
}

}  // namespace lvslam::system
