#include "lvslam/visual/optimize/bundle_adjustment.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <tuple>

#include "lvslam/core/error.h"
#include "lvslam/core/se3.h"
#include "lvslam/visual/geometry/line_projection.h"
#include "lvslam/visual/geometry/orthonormal_line.h"
#include "lvslam/visual/optimize/huber_loss.h"
#include "lvslam/visual/optimize/schur_system.h"
#include "lvslam/visual/residuals/line_direction.h"
#include "lvslam/visual/residuals/line_reprojection.h"
#include "lvslam/visual/residuals/point_depth.h"
#include "lvslam/visual/residuals/point_reprojection.h"
#include "lvslam/visual/residuals/pose_prior.h"

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

// The value of every block; variables change, constants stay.
struct Estimate {
  std::vector<Eigen::Isometry3d> poses;
  std::vector<Eigen::Vector3d> points;
  std::vector<Vector6d> lines;  // unit Plücker (m, d)
};

OrthonormalLine orthonormalOf(const Vector6d& L) { return OrthonormalLine::fromPlucker(PluckerLine::fromVector(L)); }

// w J' J and w J' r of one residual into the pose block, the landmark block
// and their coupling (IRLS weight w = rho'(|r|^2): for Huber this is what
// Ceres' loss corrector does too).
template <int R, int D>
void accumulate(SchurSystem& system, int pose, SchurLandmark<D>* landmark, int slot, double w,
                const Eigen::Matrix<double, R, 1>& r, const Eigen::Matrix<double, R, 6>& J_pose,
                const Eigen::Matrix<double, R, D>& J_landmark) {
  if (pose >= 0) {
    system.poseH(pose).noalias() += w * J_pose.transpose() * J_pose;
    system.poseG(pose).noalias() += w * J_pose.transpose() * r;
  }
  if (!landmark) return;
  landmark->H.noalias() += w * J_landmark.transpose() * J_landmark;
  landmark->g.noalias() += w * J_landmark.transpose() * r;
  if (pose >= 0) landmark->couplings[slot].noalias() += w * J_pose.transpose() * J_landmark;
}

// Levenberg-Marquardt on the local BA with every landmark eliminated
// (optimize/schur_system.h), its steps and stopping rules those of Ceres'
// trust region (Nielsen's radius update, function / parameter / gradient
// tolerances), so that the two stages behave as they did under Ceres.
class LocalBundleAdjustment {
 public:
  struct Summary {
    bool usable = false;
    double initial_cost = 0.0, final_cost = 0.0;
  };

  LocalBundleAdjustment(BundleAdjustmentProblem& p, const BundleAdjustmentConfig& config)
      : p_(p), config_(config),
        K_line_(lineProjectionMatrix(p.intrinsics.fx, p.intrinsics.fy, p.intrinsics.cx, p.intrinsics.cy)),
        x_(initialEstimate(p)),
        point_active_(p.point_observations.size(), false), depth_active_(p.point_observations.size(), false),
        line_active_(p.line_observations.size(), false), direction_active_(p.lines.size(), false),
        prior_active_(p.keyframes.size(), false) {
    numberVariables(chooseResiduals());
  }

  bool empty() const {
    const auto any = [](const std::vector<bool>& v) { return std::find(v.begin(), v.end(), true) != v.end(); };
    return !any(point_active_) && !any(line_active_) && !any(direction_active_) && !any(prior_active_);
  }

  Summary solve(int iterations) {
    Summary summary;
    std::optional<double> cost = evaluate(x_, system_.get());
    if (!cost) return summary;  // Ceres: the initial evaluation failed
    summary.usable = true;
    summary.initial_cost = summary.final_cost = *cost;
    double radius = kInitialRadius, decrease_factor = 2.0;
    SchurSystem::Step step;
    for (int it = 0; it < iterations; ++it) {
      if (system_->maxGradient() <= kGradientTolerance) break;
      const bool solved = system_->solve(1.0 / radius, step);
      if (solved && stepNorm(step) <= kParameterTolerance * (stateNorm() + kParameterTolerance)) break;
      std::optional<double> new_cost;
      double model = 0.0;
      Estimate candidate;
      if (solved) {
        candidate = plus(x_, step);
        new_cost = evaluate(candidate, nullptr);
        model = system_->modelDecrease(step);
      }
      const double decrease = new_cost ? *cost - *new_cost : 0.0;
      const bool flat = new_cost && std::abs(decrease) <= kFunctionTolerance * *cost;
      const double rho = new_cost && model > 0.0 ? decrease / model : -1.0;
      if (rho <= kMinRelativeDecrease) {
        radius /= decrease_factor;
        decrease_factor *= 2.0;
        if (flat || radius < kMinRadius) break;
        continue;
      }
      x_ = std::move(candidate);
      radius = std::min(kMaxRadius, radius / std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * rho - 1.0, 3)));
      decrease_factor = 2.0;
      cost = evaluate(x_, system_.get());
      if (!cost) return summary;  // cannot happen: the candidate evaluated
      summary.final_cost = *cost;
      if (flat) break;
    }
    return summary;
  }

  // Drops chi2 outliers (ORB-SLAM's local BA between stages).
  void classify(BundleAdjustmentResult& result) {
    for (size_t i = 0; i < point_active_.size(); ++i) {
      if (!point_active_[i]) continue;
      const BaPointObservation& o = p_.point_observations[i];
      const Eigen::Isometry3d& T = x_.poses[o.keyframe];
      Eigen::Vector2d r;
      const bool ok = PointReprojection::evaluate(T.linear(), T.translation(), x_.points[o.point], o.pixel,
                                                  p_.intrinsics, std::sqrt(o.inv_sigma2), r, nullptr, nullptr);
      point_active_[i] = result.point_inlier[i] = ok && r.squaredNorm() <= config_.chi2_point;
      if (!depth_active_[i]) continue;
      double e = 0.0;
      const bool depth_ok = point_active_[i] && PointDepth::evaluate(T.linear(), T.translation(), x_.points[o.point],
                                                                      o.depth, depthInvSigma(o), e, nullptr, nullptr);
      depth_active_[i] = result.depth_inlier[i] = depth_ok && e * e <= config_.chi2_depth;  // goes with its point
    }
    for (size_t i = 0; i < line_active_.size(); ++i) {
      if (!line_active_[i]) continue;
      const BaLineObservation& o = p_.line_observations[i];
      const Eigen::Isometry3d& T = x_.poses[o.keyframe];
      Eigen::Vector2d r;
      const bool ok = LineReprojection::evaluate(T.linear(), T.translation(), x_.lines[o.line], homogeneous(o.start),
                                                 homogeneous(o.end), K_line_, std::sqrt(o.inv_sigma2), r, nullptr,
                                                 nullptr);
      line_active_[i] = result.line_inlier[i] = ok && r.squaredNorm() <= config_.chi2_line;
    }
  }

  void writeBack() const {
    for (size_t k = 0; k < x_.poses.size(); ++k) p_.keyframes[k].T_camera_world = x_.poses[k];
    for (size_t j = 0; j < x_.points.size(); ++j) p_.points[j].p_world = x_.points[j];
    for (size_t j = 0; j < x_.lines.size(); ++j) p_.lines[j].line_world = PluckerLine::fromVector(x_.lines[j]);
  }

 private:
  // Ceres' defaults for its trust region: the damping local BA had under
  // Ceres (docs/history/2026-11-fusion-sessions.md, "Local BA without Ceres").
  static constexpr double kInitialRadius = 1e4, kMaxRadius = 1e16, kMinRadius = 1e-32;
  static constexpr double kMinRelativeDecrease = 1e-3, kFunctionTolerance = 1e-6;
  static constexpr double kParameterTolerance = 1e-8, kGradientTolerance = 1e-10;

  static Estimate initialEstimate(const BundleAdjustmentProblem& p) {
    Estimate x;
    for (const BaKeyframe& k : p.keyframes) x.poses.push_back(k.T_camera_world);
    for (const BaPoint& pt : p.points) x.points.push_back(pt.p_world);
    for (const BaLine& l : p.lines) x.lines.push_back(l.line_world.vector().normalized());
    return x;
  }

  static Eigen::Vector3d homogeneous(const Eigen::Vector2d& px) { return {px.x(), px.y(), 1.0}; }
  double depthInvSigma(const BaPointObservation& o) const { return 1.0 / (config_.depth_sigma_ratio * o.depth); }

  // The residuals that exist from the start: reprojections in front of their
  // camera (the rest are outliers from the start), depths of those, lines,
  // directions of used lines, priors of free poses the images constrain (a
  // prior alone would just copy the LiDAR). Returns the blocks some image
  // residual touches: the candidates for unknowns.
  struct Used {
    std::vector<bool> poses, points, lines;
  };

  Used chooseResiduals() {
    Used used{std::vector<bool>(p_.keyframes.size(), false), std::vector<bool>(p_.points.size(), false),
              std::vector<bool>(p_.lines.size(), false)};
    for (size_t i = 0; i < p_.point_observations.size(); ++i) {
      const BaPointObservation& o = p_.point_observations[i];
      const Eigen::Isometry3d& T = x_.poses[o.keyframe];
      Eigen::Vector2d r;
      if (!o.pixel.allFinite() || !PointReprojection::evaluate(T.linear(), T.translation(), x_.points[o.point],
                                                               o.pixel, p_.intrinsics, 1.0, r, nullptr, nullptr))
        continue;
      point_active_[i] = true;
      depth_active_[i] = std::isfinite(o.depth);
      used.poses[o.keyframe] = used.points[o.point] = true;
    }
    for (size_t i = 0; i < p_.line_observations.size(); ++i) {
      const BaLineObservation& o = p_.line_observations[i];
      if (!o.start.allFinite() || !o.end.allFinite()) continue;
      line_active_[i] = true;
      used.poses[o.keyframe] = used.lines[o.line] = true;
    }
    fusion_unit_.resize(p_.lines.size(), Eigen::Vector3d::Zero());
    for (size_t j = 0; j < p_.lines.size(); ++j) {
      const auto& d_fu = p_.lines[j].fusion_direction;
      if (!config_.use_direction_residual || !used.lines[j] || !d_fu || !(d_fu->norm() > 0.0)) continue;
      direction_active_[j] = true;
      fusion_unit_[j] = d_fu->normalized();
    }
    for (size_t k = 0; k < p_.keyframes.size(); ++k)
      prior_active_[k] = p_.keyframes[k].prior_T_camera_world && used.poses[k] && !p_.keyframes[k].fixed;
    return used;
  }

  // Unknowns: used blocks not held fixed; -1 marks a constant.
  void numberVariables(const Used& used) {
    const auto number = [](const std::vector<bool>& used, auto fixed) {
      std::vector<int> index(used.size(), -1);
      int n = 0;
      for (size_t i = 0; i < used.size(); ++i)
        if (used[i] && !fixed(i)) index[i] = n++;
      return std::make_pair(index, n);
    };
    int poses = 0, points = 0, lines = 0;
    std::tie(pose_var_, poses) = number(used.poses, [&](size_t k) { return p_.keyframes[k].fixed; });
    std::tie(point_var_, points) = number(used.points, [&](size_t j) { return p_.points[j].fixed; });
    std::tie(line_var_, lines) = number(used.lines, [&](size_t j) { return p_.lines[j].fixed; });
    system_ = std::make_unique<SchurSystem>(poses, points, lines);
    point_slot_.assign(p_.point_observations.size(), -1);
    line_slot_.assign(p_.line_observations.size(), -1);
    for (size_t i = 0; i < point_slot_.size(); ++i) {
      const BaPointObservation& o = p_.point_observations[i];
      if (point_active_[i] && pose_var_[o.keyframe] >= 0 && point_var_[o.point] >= 0)
        point_slot_[i] = system_->pointSlot(point_var_[o.point], pose_var_[o.keyframe]);
    }
    for (size_t i = 0; i < line_slot_.size(); ++i) {
      const BaLineObservation& o = p_.line_observations[i];
      if (line_active_[i] && pose_var_[o.keyframe] >= 0 && line_var_[o.line] >= 0)
        line_slot_[i] = system_->lineSlot(line_var_[o.line], pose_var_[o.keyframe]);
    }
  }

  // The total robust cost 1/2 sum rho(|r|^2) at x and, given a system, its
  // normal equations there. Empty when a residual cannot be evaluated (a
  // point behind its camera): Ceres rejects such a step too.
  std::optional<double> evaluate(const Estimate& x, SchurSystem* system) const {
    if (system) system->setZero();
    Linearization lin{system};
    std::vector<Eigen::Matrix<double, 6, 4>> plus_jacobians;
    if (system) {
      plus_jacobians.resize(x.lines.size());
      for (size_t j = 0; j < x.lines.size(); ++j)
        if (line_var_[j] >= 0) plus_jacobians[j] = orthonormalPlusJacobian(orthonormalOf(x.lines[j]));
    }
    if (!addPoints(x, lin) || !addLines(x, plus_jacobians, lin) || !addDirections(x, plus_jacobians, lin))
      return std::nullopt;
    addPriors(x, lin);
    return lin.cost;
  }

  // The robust cost of one evaluation and, with a system, its normal equations.
  struct Linearization {
    SchurSystem* system = nullptr;
    double cost = 0.0;
    // Adds 1/2 rho(s) to the cost; returns the IRLS weight rho'(s).
    double robust(double s, double delta) {
      cost += 0.5 * huberLoss(s, delta);
      return huberWeight(s, delta);
    }
  };

  // Reprojections and their LiDAR depths.
  bool addPoints(const Estimate& x, Linearization& lin) const {
    for (size_t i = 0; i < point_active_.size(); ++i) {
      if (!point_active_[i]) continue;
      const BaPointObservation& o = p_.point_observations[i];
      const Eigen::Isometry3d& T = x.poses[o.keyframe];
      const int a = lin.system ? pose_var_[o.keyframe] : -1, j = lin.system ? point_var_[o.point] : -1;
      SchurLandmark<3>* point = j >= 0 ? &lin.system->point(j) : nullptr;
      Eigen::Vector2d r;
      Eigen::Matrix<double, 2, 6> J_pose;
      Eigen::Matrix<double, 2, 3> J_point;
      if (!PointReprojection::evaluate(T.linear(), T.translation(), x.points[o.point], o.pixel, p_.intrinsics,
                                       std::sqrt(o.inv_sigma2), r, a >= 0 ? &J_pose : nullptr,
                                       point ? &J_point : nullptr))
        return false;
      const double w = lin.robust(r.squaredNorm(), config_.huber_delta);
      if (lin.system) accumulate<2, 3>(*lin.system, a, point, point_slot_[i], w, r, J_pose, J_point);
      if (!depth_active_[i]) continue;
      Eigen::Matrix<double, 1, 1> e;
      Eigen::Matrix<double, 1, 6> Jd_pose;
      Eigen::Matrix<double, 1, 3> Jd_point;
      if (!PointDepth::evaluate(T.linear(), T.translation(), x.points[o.point], o.depth, depthInvSigma(o), e[0],
                                a >= 0 ? &Jd_pose : nullptr, point ? &Jd_point : nullptr))
        return false;
      const double wd = lin.robust(e[0] * e[0], config_.depth_huber_delta);
      if (lin.system) accumulate<1, 3>(*lin.system, a, point, point_slot_[i], wd, e, Jd_pose, Jd_point);
    }
    return true;
  }

  // Endpoint distances e_dis; the line's 6x4 plus Jacobian turns d/d(m, d)
  // into d/d(orthonormal update).
  bool addLines(const Estimate& x, const std::vector<Eigen::Matrix<double, 6, 4>>& plus_jacobians,
                Linearization& lin) const {
    for (size_t i = 0; i < line_active_.size(); ++i) {
      if (!line_active_[i]) continue;
      const BaLineObservation& o = p_.line_observations[i];
      const Eigen::Isometry3d& T = x.poses[o.keyframe];
      const int a = lin.system ? pose_var_[o.keyframe] : -1, j = lin.system ? line_var_[o.line] : -1;
      SchurLandmark<4>* line = j >= 0 ? &lin.system->line(j) : nullptr;
      Eigen::Vector2d r;
      Eigen::Matrix<double, 2, 6> J_pose, J_plucker;
      if (!LineReprojection::evaluate(T.linear(), T.translation(), x.lines[o.line], homogeneous(o.start),
                                      homogeneous(o.end), K_line_, std::sqrt(o.inv_sigma2), r,
                                      a >= 0 ? &J_pose : nullptr, line ? &J_plucker : nullptr))
        return false;
      const double w = lin.robust(r.squaredNorm(), config_.huber_delta);
      if (!lin.system) continue;
      const Eigen::Matrix<double, 2, 4> J_line = line ? Eigen::Matrix<double, 2, 4>(J_plucker * plus_jacobians[o.line])
                                                      : Eigen::Matrix<double, 2, 4>::Zero();
      accumulate<2, 4>(*lin.system, a, line, line_slot_[i], w, r, J_pose, J_line);
    }
    return true;
  }

  // The paper's line direction residual e_dir against the fusion direction.
  bool addDirections(const Estimate& x, const std::vector<Eigen::Matrix<double, 6, 4>>& plus_jacobians,
                     Linearization& lin) const {
    for (size_t j = 0; j < direction_active_.size(); ++j) {
      if (!direction_active_[j]) continue;
      const int v = lin.system ? line_var_[j] : -1;
      Eigen::Matrix<double, 1, 1> e;
      Eigen::Matrix<double, 1, 3> J_d;
      if (!LineDirection::evaluate(x.lines[j].tail<3>(), fusion_unit_[j], config_.direction_weight, e[0],
                                   v >= 0 ? &J_d : nullptr))
        return false;
      const double w = lin.robust(e[0] * e[0], config_.direction_huber_delta);
      if (v < 0) continue;
      // Only d enters: the last three rows of the plus Jacobian.
      const Eigen::Matrix<double, 1, 4> J_line = J_d * plus_jacobians[j].bottomRows<3>();
      accumulate<1, 4>(*lin.system, -1, &lin.system->line(v), -1, w, e, Eigen::Matrix<double, 1, 6>::Zero(), J_line);
    }
    return true;
  }

  // LiDAR pose priors (always evaluable).
  void addPriors(const Estimate& x, Linearization& lin) const {
    const double inv_sigma_t = 1.0 / config_.prior_sigma_m;
    const double inv_sigma_r = 1.0 / (config_.prior_sigma_deg * M_PI / 180.0);
    for (size_t k = 0; k < prior_active_.size(); ++k) {
      if (!prior_active_[k]) continue;
      const int a = lin.system ? pose_var_[k] : -1;
      Eigen::Matrix<double, 6, 1> r;
      Eigen::Matrix<double, 6, 6> J;
      PosePrior::evaluate(x.poses[k], *p_.keyframes[k].prior_T_camera_world, inv_sigma_t, inv_sigma_r, r,
                          a >= 0 ? &J : nullptr);
      const double w = lin.robust(r.squaredNorm(), config_.prior_huber_delta);
      if (a >= 0) accumulate<6, 3>(*lin.system, a, nullptr, -1, w, r, J, Eigen::Matrix<double, 6, 3>::Zero());
    }
  }

  Estimate plus(const Estimate& x, const SchurSystem::Step& step) const {
    Estimate out = x;
    for (size_t k = 0; k < out.poses.size(); ++k)
      if (pose_var_[k] >= 0) out.poses[k] = leftUpdate(step.poses.segment<6>(6 * pose_var_[k]), x.poses[k]);
    for (size_t j = 0; j < out.points.size(); ++j)
      if (point_var_[j] >= 0) out.points[j] += step.points[point_var_[j]];
    for (size_t j = 0; j < out.lines.size(); ++j)
      if (line_var_[j] >= 0) out.lines[j] = orthonormalOf(x.lines[j]).plus(step.lines[line_var_[j]]).toPlucker().vector();
    return out;
  }

  double stepNorm(const SchurSystem::Step& step) const {
    double s = step.poses.squaredNorm();
    for (const Eigen::Vector3d& d : step.points) s += d.squaredNorm();
    for (const Eigen::Vector4d& d : step.lines) s += d.squaredNorm();
    return std::sqrt(s);
  }

  // |x| over the unknowns' ambient values, as Ceres measures it ([t, q] poses).
  double stateNorm() const {
    double s = 0.0;
    for (size_t k = 0; k < x_.poses.size(); ++k)
      if (pose_var_[k] >= 0) s += x_.poses[k].translation().squaredNorm() + 1.0;
    for (size_t j = 0; j < x_.points.size(); ++j)
      if (point_var_[j] >= 0) s += x_.points[j].squaredNorm();
    for (size_t j = 0; j < x_.lines.size(); ++j)
      if (line_var_[j] >= 0) s += 1.0;
    return std::sqrt(s);
  }

  BundleAdjustmentProblem& p_;
  const BundleAdjustmentConfig& config_;
  Eigen::Matrix3d K_line_;
  Estimate x_;
  std::vector<bool> point_active_, depth_active_, line_active_, direction_active_, prior_active_;
  std::vector<Eigen::Vector3d> fusion_unit_;
  std::vector<int> pose_var_, point_var_, line_var_;  // unknown index, -1: constant
  std::vector<int> point_slot_, line_slot_;            // coupling block of each observation
  std::unique_ptr<SchurSystem> system_;
};

}  // namespace

BundleAdjustmentResult runBundleAdjustment(BundleAdjustmentProblem& p, const BundleAdjustmentConfig& config) {
  validate(p);
  validate(config);
  BundleAdjustmentResult result;
  result.point_inlier.assign(p.point_observations.size(), false);
  result.line_inlier.assign(p.line_observations.size(), false);
  result.depth_inlier.assign(p.point_observations.size(), false);
  LocalBundleAdjustment ba(p, config);
  if (ba.empty()) return result;
  LocalBundleAdjustment::Summary summary = ba.solve(config.first_stage_iterations);
  result.initial_cost = summary.initial_cost;
  ba.classify(result);
  if (config.second_stage_iterations > 0 && !ba.empty()) {
    summary = ba.solve(config.second_stage_iterations);
    ba.classify(result);
  }
  result.final_cost = summary.final_cost;
  ba.writeBack();
  result.usable = summary.usable;
  return result;
}

}  // namespace lvslam::visual
