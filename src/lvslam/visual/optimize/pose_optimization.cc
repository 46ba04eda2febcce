#include "lvslam/visual/optimize/pose_optimization.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

#include "lvslam/core/se3.h"
#include "lvslam/visual/geometry/line_projection.h"
#include "lvslam/visual/optimize/huber_loss.h"
#include "lvslam/visual/residuals/line_reprojection.h"
#include "lvslam/visual/residuals/point_reprojection.h"

namespace lvslam::visual {

namespace {

struct NormalEquations {
  Matrix6d H = Matrix6d::Zero();
  Vector6d g = Vector6d::Zero();
  double cost = 0.0;
};

class PoseProblem {
 public:
  PoseProblem(const std::vector<PosePointObservation>& points,
              const std::vector<PoseLineObservation>& lines, const PinholeIntrinsics& K,
              const PoseOptimizationConfig& config)
      : points_(points), lines_(lines), K_(K), config_(config),
        K_line_(lineProjectionMatrix(K.fx, K.fy, K.cx, K.cy)) {
    line_vectors_.reserve(lines.size());
    for (const auto& l : lines) line_vectors_.push_back(l.line_world.vector().normalized());
  }

  // Accumulates over inliers; with jacobians=false only the cost.
  NormalEquations accumulate(const Eigen::Isometry3d& T, const std::vector<bool>& point_in,
                             const std::vector<bool>& line_in, bool robust, bool jacobians) const {
    NormalEquations ne;
    const Eigen::Matrix3d R = T.linear();
    const Eigen::Vector3d t = T.translation();
    Eigen::Vector2d r;
    Eigen::Matrix<double, 2, 6> J = Eigen::Matrix<double, 2, 6>::Zero();  // read only with jacobians; zeroed for -Wmaybe-uninitialized
    for (size_t i = 0; i < points_.size(); ++i) {
      if (!point_in[i]) continue;
      const auto& o = points_[i];
      if (!PointReprojection::evaluate(R, t, o.p_world, o.pixel, K_, std::sqrt(o.inv_sigma2), r,
                                       jacobians ? &J : nullptr, nullptr)) {
        ne.cost += config_.chi2_point;  // a point behind the camera costs like an outlier
        continue;
      }
      add(r, J, jacobians, robust, ne);
    }
    for (size_t i = 0; i < lines_.size(); ++i) {
      if (!line_in[i]) continue;
      const auto& o = lines_[i];
      if (!LineReprojection::evaluate(R, t, line_vectors_[i], o.start.homogeneous(), o.end.homogeneous(),
                                      K_line_, std::sqrt(o.inv_sigma2), r, jacobians ? &J : nullptr,
                                      nullptr)) {
        ne.cost += config_.chi2_line;
        continue;
      }
      add(r, J, jacobians, robust, ne);
    }
    return ne;
  }

  // Chi2 of every observation at T (infinite when it cannot be evaluated).
  void chi2(const Eigen::Isometry3d& T, std::vector<double>& point_chi2, std::vector<double>& line_chi2) const {
    const Eigen::Matrix3d R = T.linear();
    const Eigen::Vector3d t = T.translation();
    Eigen::Vector2d r;
    for (size_t i = 0; i < points_.size(); ++i) {
      const auto& o = points_[i];
      point_chi2[i] = PointReprojection::evaluate(R, t, o.p_world, o.pixel, K_, std::sqrt(o.inv_sigma2), r,
                                                  nullptr, nullptr)
                          ? r.squaredNorm()
                          : INFINITY;
    }
    for (size_t i = 0; i < lines_.size(); ++i) {
      const auto& o = lines_[i];
      line_chi2[i] = LineReprojection::evaluate(R, t, line_vectors_[i], o.start.homogeneous(),
                                                o.end.homogeneous(), K_line_, std::sqrt(o.inv_sigma2), r,
                                                nullptr, nullptr)
                         ? r.squaredNorm()
                         : INFINITY;
    }
  }

 private:
  void add(const Eigen::Vector2d& r, const Eigen::Matrix<double, 2, 6>& J, bool jacobians, bool robust,
           NormalEquations& ne) const {
    const double e2 = r.squaredNorm();
    ne.cost += robust ? huberLoss(e2, config_.huber_delta) : e2;
    if (!jacobians) return;
    const double w = robust ? huberWeight(e2, config_.huber_delta) : 1.0;
    ne.H.noalias() += w * J.transpose() * J;
    ne.g.noalias() += w * J.transpose() * r;
  }

  const std::vector<PosePointObservation>& points_;
  const std::vector<PoseLineObservation>& lines_;
  PinholeIntrinsics K_;
  PoseOptimizationConfig config_;
  Eigen::Matrix3d K_line_;
  std::vector<Vector6d> line_vectors_;
};

// Levenberg-Marquardt on the left SE3 update for a fixed inlier set.
Eigen::Isometry3d solveRound(const PoseProblem& problem, Eigen::Isometry3d T, const std::vector<bool>& point_in,
                             const std::vector<bool>& line_in, bool robust, int iterations) {
  double lambda = 1e-4;
  for (int it = 0; it < iterations; ++it) {
    const NormalEquations ne = problem.accumulate(T, point_in, line_in, robust, true);
    Matrix6d H = ne.H;
    H.diagonal() += lambda * ne.H.diagonal().cwiseMax(1e-9);
    const Vector6d delta = H.ldlt().solve(-ne.g);
    if (!delta.allFinite()) break;
    const Eigen::Isometry3d candidate = expSE3(delta) * T;
    const double new_cost = problem.accumulate(candidate, point_in, line_in, robust, false).cost;
    if (new_cost < ne.cost) {
      T = candidate;
      lambda = std::max(1e-7, lambda * 0.1);
      if (delta.squaredNorm() < 1e-14) break;
    } else {
      lambda *= 10.0;
      if (lambda > 1e6) break;
    }
  }
  return T;
}

}  // namespace

PoseOptimizationResult optimizePose(const Eigen::Isometry3d& T_camera_world_initial,
                                    const std::vector<PosePointObservation>& points,
                                    const std::vector<PoseLineObservation>& lines,
                                    const PinholeIntrinsics& intrinsics,
                                    const PoseOptimizationConfig& config) {
  PoseOptimizationResult result;
  result.T_camera_world = T_camera_world_initial;
  result.point_inlier.assign(points.size(), true);
  result.line_inlier.assign(lines.size(), true);
  if (!T_camera_world_initial.matrix().allFinite()) return result;
  for (size_t i = 0; i < points.size(); ++i) {
    result.point_inlier[i] = points[i].p_world.allFinite() && points[i].pixel.allFinite() &&
                             points[i].inv_sigma2 > 0.0 && std::isfinite(points[i].inv_sigma2);
  }
  for (size_t i = 0; i < lines.size(); ++i) {
    result.line_inlier[i] = lines[i].line_world.isValid(1e-6) && lines[i].start.allFinite() &&
                            lines[i].end.allFinite() && lines[i].inv_sigma2 > 0.0 && std::isfinite(lines[i].inv_sigma2);
  }
  // Observations unusable from the start stay outliers in every round.
  const std::vector<bool> point_usable = result.point_inlier, line_usable = result.line_inlier;
  const PoseProblem problem(points, lines, intrinsics, config);
  std::vector<double> point_chi2(points.size()), line_chi2(lines.size());
  Eigen::Isometry3d T = T_camera_world_initial;
  for (int round = 0; round < config.rounds; ++round) {
    const bool robust = round + 1 < config.rounds;  // ORB-SLAM drops the kernel at the end
    T = solveRound(problem, T, result.point_inlier, result.line_inlier, robust, config.iterations_per_round);
    // Every observation is re-tested, so early outliers can come back.
    problem.chi2(T, point_chi2, line_chi2);
    for (size_t i = 0; i < points.size(); ++i) {
      result.point_inlier[i] = point_usable[i] && point_chi2[i] <= config.chi2_point;
    }
    for (size_t i = 0; i < lines.size(); ++i) {
      result.line_inlier[i] = line_usable[i] && line_chi2[i] <= config.chi2_line;
    }
  }
  result.num_inliers = static_cast<int>(std::count(result.point_inlier.begin(), result.point_inlier.end(), true) +
                                        std::count(result.line_inlier.begin(), result.line_inlier.end(), true));
  // Re-project onto SO(3): tracking chains poses frame to frame (constant
  // velocity = T_now * T_last^-1 with a transpose for the inverse), so a
  // rounding drift away from a rotation would compound over a sequence.
  if (T.matrix().allFinite()) T.linear() = Eigen::Quaterniond(T.linear()).normalized().toRotationMatrix();
  result.T_camera_world = T;
  result.success = T.matrix().allFinite() && result.num_inliers >= config.min_inliers;
  if (result.success) result.information = problem.accumulate(T, result.point_inlier, result.line_inlier, false, true).H;
  return result;
}

}  // namespace lvslam::visual
