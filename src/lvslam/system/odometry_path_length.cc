#include "lvslam/system/odometry_path_length.h"

#include <algorithm>
#include <iterator>

namespace lvslam::system {

void OdometryPathLength::add(double t, const Eigen::Vector3d& centre) {
  if (!times_.empty() && !(t > times_.back())) return;
  const double length = times_.empty() ? 0.0 : lengths_.back() + (centre - last_).norm();
  times_.push_back(t);
  lengths_.push_back(length);
  last_ = centre;
}

std::optional<double> OdometryPathLength::at(double t) const {
  const auto after = std::upper_bound(times_.begin(), times_.end(), t);
  if (after == times_.begin()) return std::nullopt;
  return lengths_[static_cast<std::size_t>(std::distance(times_.begin(), after)) - 1];
}

double OdometryPathLength::since(double t) const {
  if (lengths_.empty()) return 0.0;
  return lengths_.back() - at(t).value_or(0.0);
}

}  // namespace lvslam::system
