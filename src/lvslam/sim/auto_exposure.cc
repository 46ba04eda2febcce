#include "lvslam/sim/auto_exposure.h"

#include <algorithm>
#include <cmath>

namespace lvslam::sim {

AutoExposure::AutoExposure(const AutoExposureConfig& config, double base_exposure, double frame_period)
    : config_(config), base_exposure_(base_exposure), alpha_(1.0 - std::exp(-frame_period / config.time_constant)) {}

Exposure AutoExposure::current() const {
  if (!config_.enabled) return {base_exposure_, 1.0};
  // Shutter first: a longer exposure costs blur but no noise.
  const double time = std::min(base_exposure_ * factor_, std::max(config_.max_exposure, base_exposure_));
  return {time, factor_ * base_exposure_ / time};
}

void AutoExposure::update(const cv::Mat& image) {
  if (!config_.enabled) return;
  const double mean = std::max(cv::mean(image)[0], 0.5);  // a black frame (blackout) asks for the most light
  const double next = std::log(factor_) + alpha_ * (std::log(config_.target) - std::log(mean));
  factor_ = std::clamp(std::exp(next), config_.min_factor, config_.max_factor);
}

}  // namespace lvslam::sim
