#include "lvslam/fusion/sphere_geometry.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace lvslam::fusion {

Eigen::Vector3d bearing(const Eigen::Vector3d& p_camera) {
  const double n = p_camera.norm();
  return n > 0.0 ? Eigen::Vector3d(p_camera / n) : Eigen::Vector3d::Zero();
}

double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  // atan2 of |a x b| and a.b keeps precision near 0 and pi, unlike acos.
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

double chordToAngle(double chord) { return 2.0 * std::asin(std::clamp(0.5 * chord, 0.0, 1.0)); }

std::vector<Eigen::Vector3d> sampleArc(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double step) {
  std::vector<Eigen::Vector3d> samples{a};
  const double theta = angleBetween(a, b);
  if (theta <= 0.0 || !(step > 0.0)) return samples;
  // Rotate a towards b about their common normal, one step at a time.
  const Eigen::Vector3d axis = a.cross(b).normalized();
  const int steps = static_cast<int>(std::floor(theta / step - 1e-9));
  for (int k = 1; k <= steps; ++k) samples.push_back(Eigen::AngleAxisd(k * step, axis) * a);
  samples.push_back(b);
  return samples;
}

}  // namespace lvslam::fusion
