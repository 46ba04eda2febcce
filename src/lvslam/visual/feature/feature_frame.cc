#include "lvslam/visual/feature/feature_frame.h"

#include <Eigen/Geometry>

namespace lvslam::visual {

Eigen::Vector3d lineCoefficients(const Eigen::Vector2d& start, const Eigen::Vector2d& end) {
  const Eigen::Vector3d l = start.homogeneous().cross(end.homogeneous());
  const double n = l.head<2>().norm();
  return n > 0.0 ? Eigen::Vector3d(l / n) : Eigen::Vector3d::Zero();
}

}  // namespace lvslam::visual
