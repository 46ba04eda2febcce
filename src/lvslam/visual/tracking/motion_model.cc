#include "lvslam/visual/tracking/motion_model.h"

#include <algorithm>
#include <cmath>

#include "lvslam/core/se3.h"

namespace lvslam::visual {

namespace {
constexpr double kMaxRepeatedSteps = 64.0;  // beyond: one scaled step (same pose, bounded work)
}

Eigen::Isometry3d predictPose(const ConstantVelocity& model, const Eigen::Isometry3d& T_last, double elapsed) {
  if (!(model.dt > 0.0) || !std::isfinite(elapsed)) return model.velocity * T_last;
  const double steps = std::max(0.0, elapsed / model.dt);
  const double whole = std::round(steps);
  if (whole >= 1.0 && whole <= kMaxRepeatedSteps && std::abs(steps - whole) < 0.25) {
    Eigen::Isometry3d T = T_last;
    for (int i = 0; i < static_cast<int>(whole); ++i) T = model.velocity * T;
    return T;
  }
  return expSE3(steps * logSE3(model.velocity)) * T_last;
}

}  // namespace lvslam::visual
