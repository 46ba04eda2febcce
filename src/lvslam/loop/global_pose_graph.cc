#include "lvslam/loop/global_pose_graph.h"

#include <memory>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <ceres/autodiff_cost_function.h>
#include <ceres/loss_function.h>
#include <ceres/manifold.h>
#include <ceres/problem.h>
#include <ceres/solver.h>

#include "lvslam/core/relative_pose_error.h"

namespace lvslam::loop {

namespace {

// Upper factor U of information = U^T U (information is positive definite
// for both edge kinds: the drift model and the ICP's plus a floor).
Matrix6d whitening(const Matrix6d& information) {
  const Eigen::LLT<Matrix6d> llt(0.5 * (information + information.transpose()));
  return llt.matrixU();
}

// Position and orientation are separate blocks (t: 3, q: x y z w).
struct EdgeResidual {
  EdgeResidual(const Eigen::Isometry3d& T_from_to, const Matrix6d& information)
      : t_z(T_from_to.translation()), q_z(Eigen::Quaterniond(T_from_to.linear())), U(whitening(information)) {}

  template <typename T>
  bool operator()(const T* t_a, const T* q_a, const T* t_b, const T* q_b, T* out) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    using Quat = Eigen::Quaternion<T>;
    const Eigen::Matrix<T, 6, 1> e = relativePoseError<T>(Eigen::Map<const Vec3>(t_a), Eigen::Map<const Quat>(q_a),
                                                          Eigen::Map<const Vec3>(t_b), Eigen::Map<const Quat>(q_b),
                                                          t_z, q_z);
    Eigen::Map<Eigen::Matrix<T, 6, 1>> r(out);
    r = U.cast<T>() * e;
    return true;
  }

  Eigen::Vector3d t_z;
  Eigen::Quaterniond q_z;
  Matrix6d U;
};

}  // namespace

double edgeChiSquare(const GraphEdge& edge, const std::vector<Eigen::Isometry3d>& poses) {
  const Eigen::Isometry3d& A = poses[static_cast<std::size_t>(edge.from)];
  const Eigen::Isometry3d& B = poses[static_cast<std::size_t>(edge.to)];
  const EdgeResidual residual(edge.T_from_to, edge.information);
  const Eigen::Quaterniond q_a(A.linear()), q_b(B.linear());
  Vector6d r;
  residual(A.translation().data(), q_a.coeffs().data(), B.translation().data(), q_b.coeffs().data(), r.data());
  return r.squaredNorm();
}

GraphSolution solveGlobalPoseGraph(const std::vector<Eigen::Isometry3d>& initial, const std::vector<GraphEdge>& edges,
                                   double kernel) {
  GraphSolution solution;
  solution.poses = initial;
  solution.edge_weights.assign(edges.size(), 1.0);
  if (initial.size() < 2 || edges.empty()) {
    solution.solved = true;
    return solution;
  }
  std::vector<Eigen::Vector3d> t(initial.size());
  std::vector<Eigen::Quaterniond> q(initial.size());
  for (std::size_t i = 0; i < initial.size(); ++i) {
    t[i] = initial[i].translation();
    q[i] = Eigen::Quaterniond(initial[i].linear()).normalized();
  }
  ceres::Problem problem;
  for (const GraphEdge& edge : edges) {
    const auto a = static_cast<std::size_t>(edge.from), b = static_cast<std::size_t>(edge.to);
    auto* cost = new ceres::AutoDiffCostFunction<EdgeResidual, 6, 3, 4, 3, 4>(
        new EdgeResidual(edge.T_from_to, edge.information));
    ceres::LossFunction* loss = edge.robust ? new ceres::CauchyLoss(kernel) : nullptr;
    problem.AddResidualBlock(cost, loss, t[a].data(), q[a].coeffs().data(), t[b].data(), q[b].coeffs().data());
  }
  for (std::size_t i = 0; i < initial.size(); ++i)
    if (problem.HasParameterBlock(q[i].coeffs().data()))
      problem.SetManifold(q[i].coeffs().data(), new ceres::EigenQuaternionManifold);
  if (problem.HasParameterBlock(t[0].data())) {
    problem.SetParameterBlockConstant(t[0].data());
    problem.SetParameterBlockConstant(q[0].coeffs().data());
  }
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  options.max_num_iterations = 100;
  options.function_tolerance = 1e-10;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  solution.solved = summary.IsSolutionUsable();
  if (!solution.solved) return solution;
  for (std::size_t i = 0; i < initial.size(); ++i) solution.poses[i] = makePose(q[i].normalized(), t[i]);
  for (std::size_t k = 0; k < edges.size(); ++k)
    if (edges[k].robust)
      solution.edge_weights[k] = 1.0 / (1.0 + edgeChiSquare(edges[k], solution.poses) / (kernel * kernel));
  return solution;
}

}  // namespace lvslam::loop
