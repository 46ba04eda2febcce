#include "lvslam/lidar/adaptive_threshold.h"

#include <algorithm>
#include <cmath>

#include "lvslam/core/se3.h"

namespace lvslam::lidar {

namespace {
// Deviations below this are noise of a standing robot (kiss-icp's
// min_motion_th, 0.1 m by default there).
constexpr double kMinMotion = 0.05;  // metres
}  // namespace

void AdaptiveThreshold::update(const Eigen::Isometry3d& model_deviation) {
  const double theta = rotationAngle(model_deviation);
  const double deviation = 2.0 * max_range_ * std::sin(theta / 2.0) + model_deviation.translation().norm();
  if (deviation < kMinMotion) return;
  sum_sq_ += deviation * deviation;
  ++count_;
}

double AdaptiveThreshold::threshold() const {
  if (count_ == 0) return std::clamp(initial_, min_, max_);
  return std::clamp(3.0 * std::sqrt(sum_sq_ / static_cast<double>(count_)), min_, max_);
}

}  // namespace lvslam::lidar
