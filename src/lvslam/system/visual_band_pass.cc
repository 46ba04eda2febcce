#include "lvslam/system/visual_band_pass.h"

#include <cmath>

namespace lvslam::system {

namespace {

// d at frame i smoothed by a centred Gaussian of width sigma over frames
// [begin, end); sigma 0 is d itself.
Eigen::Vector3d smoothed(const std::vector<VisualDifference>& frames, std::size_t begin, std::size_t end,
                         std::size_t i, double sigma) {
  if (sigma <= 0.0) return *frames[i].d;
  const double span = 3.0 * sigma;
  std::size_t first = i;
  while (first > begin && frames[i].t - frames[first - 1].t <= span) --first;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double weights = 0.0;
  for (std::size_t k = first; k < end && frames[k].t - frames[i].t <= span; ++k) {
    const double u = (frames[k].t - frames[i].t) / sigma;
    const double w = std::exp(-0.5 * u * u);
    sum += w * *frames[k].d;
    weights += w;
  }
  return sum / weights;
}

}  // namespace

std::vector<Eigen::Vector3d> visualBandPass(const std::vector<VisualDifference>& frames,
                                            const VisualBandPassConfig& config) {
  std::vector<Eigen::Vector3d> corrections(frames.size(), Eigen::Vector3d::Zero());
  if (config.gain == 0.0 && config.gain_vertical == 0.0) return corrections;
  const Eigen::Vector3d gains(config.gain, config.gain, config.gain_vertical);
  std::size_t begin = 0;
  while (begin < frames.size()) {
    if (!frames[begin].d) {
      ++begin;
      continue;
    }
    std::size_t end = begin + 1;
    while (end < frames.size() && frames[end].d && frames[end].map_id == frames[begin].map_id) ++end;
    for (std::size_t i = begin; i < end; ++i)
      corrections[i] = gains.cwiseProduct(smoothed(frames, begin, end, i, config.sigma_fast_s) -
                                          smoothed(frames, begin, end, i, config.sigma_s));
    begin = end;
  }
  return corrections;
}

}  // namespace lvslam::system
