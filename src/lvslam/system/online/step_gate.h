#pragma once
// A subsystem's step judged against its own previous steps: the pose it
// reports now, predicted from its last two accepted poses at constant
// velocity, may differ by what its stated noise and the platform's
// acceleration explain (chi-square at 99.9 % on the directions it
// observes). A larger difference is a jump (a glitch, a wrong
// relocalisation, a registration into the wrong place), and the step is
// gated out. A jump that lasts (accept_after gated steps in a row) is a new
// start: it is accepted and restarted() says so, so the estimator can let
// that subsystem's frame absorb it instead of refusing it for ever.
// The same innovations say whether the subsystem's stated noise is right:
// noiseScale() is its variance multiplier by covariance matching (Mehra
// 1972, adaptive filtering): the running mean of the squared innovation
// beyond what the acceleration explains, over what the stated noise says
// (translation; at least 1). The ICP's J^T J / sigma^2 and the tracker's
// Hessian both assume independent residuals and state far less noise than
// their poses show; weighed by the noise their steps show, neither is
// gated for its ordinary jitter.
#include <deque>
#include <optional>
#include <string>

#include "lvslam/core/trajectory.h"
#include "lvslam/system/online/pose_graph.h"

namespace lvslam::system {

struct GateEvent {
  double t = 0.0;
  FactorSource source = FactorSource::kLidar;
  double chi_square = 0.0, threshold = 0.0;
  std::string reason;
};

struct StepGateConfig {
  double accel = 2.0;               // m/s^2, 1 sigma
  double angular_accel_rad = 6.0;   // rad/s^2, 1 sigma
  int accept_after = 3;             // gated steps in a row before a jump counts as a new start
  double noise_memory = 30.0;       // steps the noise scale's running mean remembers
};

class StepGate {
 public:
  StepGate(FactorSource source, const StepGateConfig& config) : source_(source), config_(config) {}

  // T_frame_camera in the subsystem's own frame; `information` its stated
  // information (camera-frame right perturbation). Returns the event when
  // the step is gated; `alone` (no other subsystem this frame): never gated,
  // as nothing better would take its place.
  std::optional<GateEvent> check(double t, const Eigen::Isometry3d& T_frame_camera, const Matrix6d& information,
                                 bool alone = false);
  // The subsystem's frame changed under it (a visual map corrected: earlier
  // poses are T_new_old * T) or was replaced (a new map: forget).
  void moveHistory(const Eigen::Isometry3d& T_new_old);
  void reset() { history_.clear(); gated_in_row_ = 0; }
  // The last accepted step ended a run of gated ones: a lasting jump.
  bool restarted() const { return restarted_; }
  // Multiplies the subsystem's stated covariance (1: as stated).
  double noiseScale() const { return noise_scale_; }

 private:
  void updateNoiseScale(const Vector6d& innovation, const Matrix6d& stated, const Matrix6d& process);

  FactorSource source_;
  StepGateConfig config_;
  std::deque<StampedPose> history_;  // the last two accepted poses
  int gated_in_row_ = 0;
  bool restarted_ = false;
  double noise_scale_ = 1.0;
};

}  // namespace lvslam::system
