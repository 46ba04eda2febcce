#include "lvslam/system/online/step_gate.h"

#include <algorithm>

#include <fmt/format.h>

#include "lvslam/system/online/pose_information.h"

namespace lvslam::system {

std::optional<GateEvent> StepGate::check(double t, const Eigen::Isometry3d& T_frame_camera,
                                         const Matrix6d& information, bool alone) {
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
  const Matrix6d stated = (1.0 + (1.0 + r) * (1.0 + r) + r * r) * noise.inverse;
  const Matrix6d process = isotropicCovariance(config_.accel * dt * dt, config_.angular_accel_rad * dt * dt);
  const Vector6d innovation = poseDifference(predicted, T_frame_camera);
  const Matrix6d covariance = noise_scale_ * stated + process;
  updateNoiseScale(innovation, stated, process);
  const Eigen::VectorXd d = noise.range.transpose() * innovation;
  const Eigen::MatrixXd S = noise.range.transpose() * covariance * noise.range;
  const double chi_square = d.dot(S.ldlt().solve(d));
  const double threshold = chiSquare999(noise.rank);
  if (chi_square <= threshold || alone) return accept();
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

void StepGate::updateNoiseScale(const Vector6d& innovation, const Matrix6d& stated, const Matrix6d& process) {
  const double stated_m2 = stated.topLeftCorner<3, 3>().trace();
  if (!(stated_m2 > 0.0)) return;
  const double excess = innovation.head<3>().squaredNorm() - process.topLeftCorner<3, 3>().trace();
  // One sample moves the scale by at most 3 / noise_memory of itself: a
  // single jump barely counts, a lasting noise is learnt within a few
  // seconds at 15 Hz.
  const double sample = std::clamp(excess / stated_m2, 1.0, 4.0 * noise_scale_);
  noise_scale_ += (sample - noise_scale_) / config_.noise_memory;
}

void StepGate::moveHistory(const Eigen::Isometry3d& T_new_old) {
  for (StampedPose& pose : history_) pose.T_world_frame = T_new_old * pose.T_world_frame;
}

}  // namespace lvslam::system
