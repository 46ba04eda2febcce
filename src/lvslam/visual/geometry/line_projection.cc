#include "lvslam/visual/geometry/line_projection.h"

namespace lvslam::visual {

Eigen::Matrix3d lineProjectionMatrix(double fx, double fy, double cx, double cy) {
  Eigen::Matrix3d K_line;
  K_line << fy, 0.0, 0.0, 0.0, fx, 0.0, -fy * cx, -fx * cy, fx * fy;
  return K_line;
}

std::optional<SegmentEndpoints3d> segmentEndpointsOnLine(const PluckerLine& line_camera,
                                                         const Eigen::Matrix3d& K,
                                                         const Eigen::Vector2d& start_px,
                                                         const Eigen::Vector2d& end_px) {
  const Eigen::Matrix3d K_inv = K.inverse();
  SegmentEndpoints3d out;
  const Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  if (!line_camera.closestPointToRay(origin, K_inv * start_px.homogeneous(), out.start) ||
      !line_camera.closestPointToRay(origin, K_inv * end_px.homogeneous(), out.end)) {
    return std::nullopt;
  }
  if (!(out.start.z() > 0.0) || !(out.end.z() > 0.0)) return std::nullopt;
  return out;
}

}  // namespace lvslam::visual
