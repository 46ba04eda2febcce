#include "lvslam/visual/geometry/line_triangulation.h"

#include <cmath>

#include "lvslam/visual/geometry/line_projection.h"

namespace lvslam::visual {

Eigen::Matrix4d dualPluckerMatrix(const Eigen::Vector4d& pi1, const Eigen::Vector4d& pi2) {
  return pi1 * pi2.transpose() - pi2 * pi1.transpose();
}

PluckerLine lineFromDualPlucker(const Eigen::Matrix4d& L_star) {
  // pi1 pi2^T - pi2 pi1^T = -[[d]x m; -m^T 0] for d = n1 x n2 and
  // m = e1 n2 - e2 n1; the common sign does not change the line.
  return PluckerLine{L_star.block<3, 1>(0, 3), Eigen::Vector3d(L_star(2, 1), L_star(0, 2), L_star(1, 0))};
}

Eigen::Vector4d backProjectedPlane(const Eigen::Matrix3d& K, const LineView& view) {
  // Camera-frame plane (K^T l, 0) through the centre; planes map with T^T.
  const Eigen::Vector3d l = view.start.homogeneous().cross(view.end.homogeneous());
  Eigen::Vector4d pi_camera;
  pi_camera << K.transpose() * l, 0.0;
  return view.T_camera_world.matrix().transpose() * pi_camera;
}

namespace {
bool finite(const LineView& v) {
  return v.start.allFinite() && v.end.allFinite() && v.T_camera_world.matrix().allFinite() &&
         (v.end - v.start).norm() > 1e-9;
}

bool endpointsInFront(const PluckerLine& line_world, const Eigen::Matrix3d& K, const LineView& view,
                      double max_depth, SegmentEndpoints3d* endpoints_camera) {
  const PluckerLine line_camera = line_world.transformed(view.T_camera_world);
  const auto ends = segmentEndpointsOnLine(line_camera, K, view.start, view.end);
  if (!ends || ends->start.z() > max_depth || ends->end.z() > max_depth) return false;
  if (endpoints_camera) *endpoints_camera = *ends;
  return true;
}
}  // namespace

std::optional<TriangulatedLine> triangulateLine(const Eigen::Matrix3d& K, const LineView& view1,
                                                const LineView& view2,
                                                const LineTriangulationConfig& config) {
  if (!finite(view1) || !finite(view2)) return std::nullopt;
  const Eigen::Vector4d pi1 = backProjectedPlane(K, view1);
  const Eigen::Vector4d pi2 = backProjectedPlane(K, view2);
  const Eigen::Vector3d n1 = pi1.head<3>().normalized(), n2 = pi2.head<3>().normalized();
  const double sin_angle = n1.cross(n2).norm();
  const double angle_deg = std::asin(std::min(1.0, sin_angle)) * 180.0 / M_PI;
  if (!(angle_deg >= config.min_plane_angle_deg)) return std::nullopt;

  const PluckerLine line = lineFromDualPlucker(dualPluckerMatrix(pi1, pi2)).normalized();
  if (!line.isValid(1e-6)) return std::nullopt;
  SegmentEndpoints3d ends1;
  if (!endpointsInFront(line, K, view1, config.max_depth, &ends1) ||
      !endpointsInFront(line, K, view2, config.max_depth, nullptr)) {
    return std::nullopt;
  }
  const Eigen::Isometry3d T_world_camera1 = view1.T_camera_world.inverse();
  return TriangulatedLine{line, T_world_camera1 * ends1.start, T_world_camera1 * ends1.end, angle_deg};
}

}  // namespace lvslam::visual
