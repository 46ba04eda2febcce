#pragma once
// Correspondence distance from how far the constant-velocity prediction has
// recently been off (kiss-icp, Vizzo et al. RA-L 2023, Sec. IV-C): 3 sigma of
// the model deviation seen at the largest range.
#include <cstddef>

#include <Eigen/Geometry>

namespace lvslam::lidar {

class AdaptiveThreshold {
 public:
  AdaptiveThreshold(double initial, double min, double max, double max_range)
      : initial_(initial), min_(min), max_(max), max_range_(max_range) {}

  // Record how the registration corrected the prediction (T_pred^-1 * T_est).
  void update(const Eigen::Isometry3d& model_deviation);
  double threshold() const;

 private:
  double initial_, min_, max_, max_range_;
  double sum_sq_ = 0.0;
  std::size_t count_ = 0;
};

}  // namespace lvslam::lidar
