#include "lvslam/system/visual_high_pass.h"

#include <cmath>

namespace lvslam::system {

Eigen::Vector3d VisualHighPass::add(double t, int map_id, const std::optional<Eigen::Vector3d>& difference) {
  if (!difference || map_id != map_id_) window_.clear();
  map_id_ = map_id;
  if (!difference || (config_.gain == 0.0 && config_.gain_vertical == 0.0)) return Eigen::Vector3d::Zero();
  const double span = 3.0 * config_.sigma_s;
  while (!window_.empty() && t - window_.front().t > span) window_.pop_front();
  window_.push_back({t, *difference});
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  double weights = 0.0;
  for (const Sample& s : window_) {
    const double u = (t - s.t) / config_.sigma_s;
    const double w = std::exp(-0.5 * u * u);
    mean += w * s.d;
    weights += w;
  }
  const Eigen::Vector3d gains(config_.gain, config_.gain, config_.gain_vertical);
  return gains.cwiseProduct(*difference - mean / weights);
}

}  // namespace lvslam::system
