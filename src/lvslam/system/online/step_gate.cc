#include "lvslam/system/online/step_gate.h"

#include <fmt/format.h>

#include "lvslam/system/online/pose_information.h"

namespace lvslam::system {

std::optional<GateEvent> StepGate::check(double t, const Eigen::Isometry3d& T_frame_camera,
                                         const Matrix6d& information) {
  restarted_ = false;
  const auto accept = [&] {
    history_.push_back({t, T_frame_camera});
    while (history_.size() > 2) history_.pop_front();
    gated_in_row_ = 0;
    return std::nullopt;
  };
  if (history_.size() < 2) return accept();
  const StampedPose& before = history_[0];
  const StampedPose& last = history_[1];
  const double dt = t - last.t, dt_before = last.t - before.t;
  if (!(dt > 0.0 && dt_before > 0.0)) return accept();
  // Constant velocity: the last step scaled to this one's length.
  const double r = dt / dt_before;
  const Eigen::Isometry3d predicted =
      last.T_world_frame * expSE3(logSE3(before.T_world_frame.inverse() * last.T_world_frame) * r);
  const PseudoInverse noise = pseudoInverse(information);
  if (noise.rank == 0) return accept();
  // Extrapolation carries the noise of the two poses it starts from
  // ((1 + r)^2 + r^2 of it) besides this pose's own, and the acceleration
  // over the step moves the pose by about a dt^2.
  const Matrix6d covariance = (1.0 + (1.0 + r) * (1.0 + r) + r * r) * noise.inverse +
                              isotropicCovariance(config_.accel * dt * dt, config_.angular_accel_rad * dt * dt);
  const Eigen::VectorXd d = noise.range.transpose() * poseDifference(predicted, T_frame_camera);
  const Eigen::MatrixXd S = noise.range.transpose() * covariance * noise.range;
  const double chi_square = d.dot(S.ldlt().solve(d));
  const double threshold = chiSquare999(noise.rank);
  if (chi_square <= threshold) return accept();
  if (++gated_in_row_ > config_.accept_after) {
    history_.clear();
    accept();
    restarted_ = true;
    return std::nullopt;
  }
  const Eigen::Vector3d jump = (predicted.inverse() * T_frame_camera).translation();
  return GateEvent{t, source_, chi_square, threshold,
                   fmt::format("{} step {:.3f} m from its own constant-velocity prediction (chi2 {:.1f} > {:.1f})",
                               factorSourceName(source_), jump.norm(), chi_square, threshold)};
}

void StepGate::moveHistory(const Eigen::Isometry3d& T_new_old) {
  for (StampedPose& pose : history_) pose.T_world_frame = T_new_old * pose.T_world_frame;
}

}  // namespace lvslam::system
