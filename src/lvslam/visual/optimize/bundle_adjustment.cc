#include "lvslam/visual/optimize/bundle_adjustment.h"

#include <array>
#include <cmath>
#include <memory>
#include <string>

#include <ceres/loss_function.h>
#include <ceres/manifold.h>
#include <ceres/ordered_groups.h>
#include <ceres/problem.h>
#include <ceres/solver.h>

#include "lvslam/core/error.h"
#include "lvslam/visual/geometry/line_projection.h"
#include "lvslam/visual/residuals/line_direction.h"
#include "lvslam/visual/residuals/line_reprojection.h"
#include "lvslam/visual/residuals/orthonormal_line_manifold.h"
#include "lvslam/visual/residuals/point_depth.h"
#include "lvslam/visual/residuals/point_reprojection.h"
#include "lvslam/visual/residuals/pose_prior.h"
#include "lvslam/visual/residuals/se3_manifold.h"

namespace lvslam::visual {

namespace {

constexpr const char* kWhere = "runBundleAdjustment";

void checkIndex(int index, size_t size, const char* what, size_t observation) {
  if (index < 0 || static_cast<size_t>(index) >= size) {
    throw Error(kWhere, std::string(what) + " index " + std::to_string(index) + " of observation " +
                            std::to_string(observation) + " is out of range (size " +
                            std::to_string(size) + ")");
  }
}

void validate(const BundleAdjustmentProblem& p) {
  auto checkWeight = [](double inv_sigma2, size_t i) {
    if (!(inv_sigma2 > 0.0) || !std::isfinite(inv_sigma2)) {
      throw Error(kWhere, "observation " + std::to_string(i) + " has a non-positive inv_sigma2");
    }
  };
  for (size_t i = 0; i < p.point_observations.size(); ++i) {
    checkIndex(p.point_observations[i].keyframe, p.keyframes.size(), "keyframe", i);
    checkIndex(p.point_observations[i].point, p.points.size(), "point", i);
    checkWeight(p.point_observations[i].inv_sigma2, i);
    const double depth = p.point_observations[i].depth;
    if (std::isfinite(depth) && !(depth > 0.0)) {
      throw Error(kWhere, "observation " + std::to_string(i) + " has a non-positive depth");
    }
  }
  for (size_t i = 0; i < p.line_observations.size(); ++i) {
    checkIndex(p.line_observations[i].keyframe, p.keyframes.size(), "keyframe", i);
    checkIndex(p.line_observations[i].line, p.lines.size(), "line", i);
    checkWeight(p.line_observations[i].inv_sigma2, i);
  }
  for (const BaLine& l : p.lines) {
    if (!l.line_world.isValid(1e-6)) throw Error(kWhere, "a line landmark is not a valid Plücker line");
  }
  for (size_t k = 0; k < p.keyframes.size(); ++k) {
    const auto& prior = p.keyframes[k].prior_T_camera_world;
    if (prior && !isRigidTransform(*prior))
      throw Error(kWhere, "the pose prior of keyframe " + std::to_string(k) + " is not a finite rigid transform");
  }
}

void validate(const BundleAdjustmentConfig& c) {
  if (!(c.depth_sigma_ratio > 0.0) || !(c.depth_huber_delta > 0.0))
    throw Error(kWhere, "depth_sigma_ratio and depth_huber_delta must be positive");
  if (!(c.prior_sigma_m > 0.0) || !(c.prior_sigma_deg > 0.0) || !(c.prior_huber_delta > 0.0))
    throw Error(kWhere, "prior_sigma_m, prior_sigma_deg and prior_huber_delta must be positive");
}

// Parameter storage, one contiguous block per variable.
struct Blocks {
  std::vector<PoseBlock> poses;
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<double, kLineBlockSize>> lines;
};

Blocks makeBlocks(const BundleAdjustmentProblem& p) {
  Blocks b;
  for (const BaKeyframe& k : p.keyframes) b.poses.push_back(toPoseBlock(k.T_camera_world));
  for (const BaPoint& pt : p.points) b.points.push_back({pt.p_world.x(), pt.p_world.y(), pt.p_world.z()});
  for (const BaLine& l : p.lines) {
    const Vector6d v = l.line_world.vector().normalized();
    b.lines.push_back({v[0], v[1], v[2], v[3], v[4], v[5]});
  }
  return b;
}

ceres::Solver::Options solverOptions(const BundleAdjustmentConfig& config, int iterations) {
  ceres::Solver::Options o;
  o.linear_solver_type = ceres::SPARSE_SCHUR;  // lines join the poses in the reduced system
  // Eigen's sparse Cholesky: as fast as CHOLMOD on these small reduced
  // systems (docs/benchmarks.md), with no BLAS threads beside ours.
  o.sparse_linear_algebra_library_type = ceres::EIGEN_SPARSE;
  o.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  o.max_num_iterations = iterations;
  o.num_threads = config.num_threads;
  o.logging_type = ceres::SILENT;
  o.minimizer_progress_to_stdout = false;
  return o;
}

// Squared whitened residual (no loss) of a residual block of 1 or 2 rows (a
// 1-row block leaves r[1] at 0).
double chi2Of(const ceres::Problem& problem, ceres::ResidualBlockId id) {
  double cost = 0.0;
  std::array<double, 2> r{};
  if (!problem.EvaluateResidualBlock(id, false, &cost, r.data(), nullptr)) return INFINITY;
  return r[0] * r[0] + r[1] * r[1];
}

// The Ceres problem of one BA run: parameter blocks, residuals and their ids.
class CeresBundleAdjustment {
 public:
  CeresBundleAdjustment(BundleAdjustmentProblem& p, const BundleAdjustmentConfig& config)
      : p_(p), config_(config), b_(makeBlocks(p)), huber_(config.huber_delta),
        direction_huber_(config.direction_huber_delta), depth_huber_(config.depth_huber_delta),
        prior_huber_(config.prior_huber_delta),
        problem_(problemOptions()),
        K_line_(lineProjectionMatrix(p.intrinsics.fx, p.intrinsics.fy, p.intrinsics.cx, p.intrinsics.cy)),
        point_ids_(p.point_observations.size(), nullptr), depth_ids_(p.point_observations.size(), nullptr),
        line_ids_(p.line_observations.size(), nullptr),
        pose_used_(b_.poses.size(), false), point_used_(b_.points.size(), false), line_used_(b_.lines.size(), false) {
    addPointResiduals();
    addDepthResiduals();
    addLineResiduals();
    addPriorResiduals();
    configureBlocks();
  }

  bool empty() const { return problem_.NumResidualBlocks() == 0; }

  ceres::Solver::Summary solve(int iterations) {
    ceres::Solver::Summary summary;
    ceres::Solver::Options options = solverOptions(config_, iterations);
    options.linear_solver_ordering = eliminationOrdering();
    ceres::Solve(options, &problem_, &summary);
    return summary;
  }

  // Drops chi2 outliers from the problem (ORB-SLAM's local BA between stages).
  void classify(BundleAdjustmentResult& result) {
    classify(point_ids_, result.point_inlier, config_.chi2_point);
    for (size_t i = 0; i < depth_ids_.size(); ++i) {  // an outlier observation takes its depth along
      if (depth_ids_[i] && !point_ids_[i]) {
        problem_.RemoveResidualBlock(depth_ids_[i]);
        depth_ids_[i] = nullptr;
        result.depth_inlier[i] = false;
      }
    }
    classify(depth_ids_, result.depth_inlier, config_.chi2_depth);
    classify(line_ids_, result.line_inlier, config_.chi2_line);
  }

  void writeBack() const {
    for (size_t k = 0; k < b_.poses.size(); ++k) p_.keyframes[k].T_camera_world = fromPoseBlock(b_.poses[k].data());
    for (size_t j = 0; j < b_.points.size(); ++j) p_.points[j].p_world = Eigen::Vector3d(b_.points[j].data());
    for (size_t j = 0; j < b_.lines.size(); ++j) {
      p_.lines[j].line_world = PluckerLine::fromVector(Eigen::Map<const Vector6d>(b_.lines[j].data()));
    }
  }

 private:
  static ceres::Problem::Options problemOptions() {
    ceres::Problem::Options o;
    o.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    o.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    o.enable_fast_removal = true;
    return o;
  }

  void addPointResiduals() {
    const PinholeIntrinsics& K = p_.intrinsics;
    for (size_t i = 0; i < p_.point_observations.size(); ++i) {
      const BaPointObservation& o = p_.point_observations[i];
      const double sqrt_info = std::sqrt(o.inv_sigma2);
      const Eigen::Isometry3d& T = p_.keyframes[o.keyframe].T_camera_world;
      Eigen::Vector2d r;
      if (!o.pixel.allFinite() || !PointReprojection::evaluate(T.linear(), T.translation(), p_.points[o.point].p_world,
                                                               o.pixel, K, sqrt_info, r, nullptr, nullptr)) {
        continue;  // behind the camera or bad input: an outlier from the start
      }
      point_ids_[i] = problem_.AddResidualBlock(new PointReprojectionCost(o.pixel, K, sqrt_info), &huber_,
                                                b_.poses[o.keyframe].data(), b_.points[o.point].data());
      pose_used_[o.keyframe] = point_used_[o.point] = true;
    }
  }

  // Only observations whose reprojection term exists (in front of the camera).
  void addDepthResiduals() {
    for (size_t i = 0; i < p_.point_observations.size(); ++i) {
      const BaPointObservation& o = p_.point_observations[i];
      if (!point_ids_[i] || !std::isfinite(o.depth)) continue;
      const double inv_sigma = 1.0 / (config_.depth_sigma_ratio * o.depth);
      depth_ids_[i] = problem_.AddResidualBlock(new PointDepthCost(o.depth, inv_sigma), &depth_huber_,
                                                b_.poses[o.keyframe].data(), b_.points[o.point].data());
    }
  }

  void addLineResiduals() {
    for (size_t i = 0; i < p_.line_observations.size(); ++i) {
      const BaLineObservation& o = p_.line_observations[i];
      if (!o.start.allFinite() || !o.end.allFinite()) continue;
      line_ids_[i] = problem_.AddResidualBlock(
          new LineReprojectionCost(o.start, o.end, K_line_, std::sqrt(o.inv_sigma2)), &huber_,
          b_.poses[o.keyframe].data(), b_.lines[o.line].data());
      pose_used_[o.keyframe] = line_used_[o.line] = true;
    }
    for (size_t j = 0; j < b_.lines.size(); ++j) {
      const auto& d_fu = p_.lines[j].fusion_direction;
      if (!config_.use_direction_residual || !line_used_[j] || !d_fu || !(d_fu->norm() > 0.0)) continue;
      problem_.AddResidualBlock(new LineDirectionCost(*d_fu, config_.direction_weight), &direction_huber_,
                                b_.lines[j].data());
    }
  }

  // Only for poses the images constrain: a prior alone would just copy the LiDAR.
  void addPriorResiduals() {
    const double sigma_r = config_.prior_sigma_deg * M_PI / 180.0;
    for (size_t k = 0; k < b_.poses.size(); ++k) {
      const auto& prior = p_.keyframes[k].prior_T_camera_world;
      if (!prior || !pose_used_[k] || p_.keyframes[k].fixed) continue;
      problem_.AddResidualBlock(new PosePriorCost(*prior, config_.prior_sigma_m, sigma_r), &prior_huber_,
                                b_.poses[k].data());
    }
  }

  void configureBlocks() {
    for (size_t k = 0; k < b_.poses.size(); ++k) {
      if (!pose_used_[k]) continue;
      problem_.SetManifold(b_.poses[k].data(), &pose_manifold_);
      if (p_.keyframes[k].fixed) problem_.SetParameterBlockConstant(b_.poses[k].data());
    }
    for (size_t j = 0; j < b_.points.size(); ++j) {
      if (point_used_[j] && p_.points[j].fixed) problem_.SetParameterBlockConstant(b_.points[j].data());
    }
    for (size_t j = 0; j < b_.lines.size(); ++j) {
      if (!line_used_[j]) continue;
      problem_.SetManifold(b_.lines[j].data(), &line_manifold_);
      if (p_.lines[j].fixed) problem_.SetParameterBlockConstant(b_.lines[j].data());
    }
  }

  // Points are eliminated first, poses and lines form the reduced system.
  // Ceres' own choice also eliminates the lines, and the mixed block sizes
  // then run its generic Schur kernels; with points alone it uses the
  // fixed-size <2, 3, 6> ones. Null (automatic) when no point takes part.
  // Ceres orders a group by address: poses and lines get a group each, since
  // their two vectors lie in the heap in no fixed order (--deterministic).
  std::shared_ptr<ceres::ParameterBlockOrdering> eliminationOrdering() {
    auto ordering = std::make_shared<ceres::ParameterBlockOrdering>();
    for (size_t j = 0; j < b_.points.size(); ++j)
      if (point_used_[j]) ordering->AddElementToGroup(b_.points[j].data(), 0);
    if (ordering->NumElements() == 0) return nullptr;
    for (size_t k = 0; k < b_.poses.size(); ++k)
      if (pose_used_[k]) ordering->AddElementToGroup(b_.poses[k].data(), 1);
    for (size_t j = 0; j < b_.lines.size(); ++j)
      if (line_used_[j]) ordering->AddElementToGroup(b_.lines[j].data(), 2);
    return ordering;
  }

  void classify(std::vector<ceres::ResidualBlockId>& ids, std::vector<bool>& inlier, double chi2) {
    for (size_t i = 0; i < ids.size(); ++i) {
      if (!ids[i]) continue;
      inlier[i] = chi2Of(problem_, ids[i]) <= chi2;
      if (!inlier[i]) {
        problem_.RemoveResidualBlock(ids[i]);
        ids[i] = nullptr;
      }
    }
  }

  BundleAdjustmentProblem& p_;
  const BundleAdjustmentConfig& config_;
  Blocks b_;
  Se3LeftManifold pose_manifold_;
  OrthonormalLineManifold line_manifold_;
  ceres::HuberLoss huber_, direction_huber_, depth_huber_, prior_huber_;
  ceres::Problem problem_;  // after the manifolds and losses it borrows
  Eigen::Matrix3d K_line_;
  std::vector<ceres::ResidualBlockId> point_ids_, depth_ids_, line_ids_;
  std::vector<bool> pose_used_, point_used_, line_used_;
};

}  // namespace

BundleAdjustmentResult runBundleAdjustment(BundleAdjustmentProblem& p, const BundleAdjustmentConfig& config) {
  validate(p);
  validate(config);
  BundleAdjustmentResult result;
  result.point_inlier.assign(p.point_observations.size(), false);
  result.line_inlier.assign(p.line_observations.size(), false);
  result.depth_inlier.assign(p.point_observations.size(), false);
  CeresBundleAdjustment ba(p, config);
  if (ba.empty()) return result;
  ceres::Solver::Summary summary = ba.solve(config.first_stage_iterations);
  result.initial_cost = summary.initial_cost;
  ba.classify(result);
  if (config.second_stage_iterations > 0 && !ba.empty()) {
    summary = ba.solve(config.second_stage_iterations);
    ba.classify(result);
  }
  result.final_cost = summary.final_cost;
  ba.writeBack();
  result.usable = summary.IsSolutionUsable();
  return result;
}

}  // namespace lvslam::visual
