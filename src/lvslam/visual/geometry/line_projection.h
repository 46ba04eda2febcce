#pragma once
// Pinhole projection of Plücker lines: the image line of a 3D line with
// moment m_c in the camera frame is l' = K_line m_c (Zhang et al. 2015,
// "Building a 3-D line-based map"; the projection used by Structure PLP).
#include <optional>

#include <Eigen/Core>

#include "lvslam/core/plucker_line.h"

namespace lvslam::visual {

// K_line = [fy 0 0; 0 fx 0; -fy cx  -fx cy  fx fy], i.e. det(K) K^-T.
Eigen::Matrix3d lineProjectionMatrix(double fx, double fy, double cx, double cy);

// Image line l' (pixels, not normalised) of a line given in the camera frame.
inline Eigen::Vector3d projectLine(const Eigen::Matrix3d& K_line, const PluckerLine& line_camera) {
  return K_line * line_camera.m;
}

// The two 3D endpoints of a segment: where the rays through its (undistorted)
// pixel endpoints come closest to the line, in the camera frame. None when a
// ray is parallel to the line or a point would lie behind the camera.
struct SegmentEndpoints3d {
  Eigen::Vector3d start, end;
};
std::optional<SegmentEndpoints3d> segmentEndpointsOnLine(const PluckerLine& line_camera,
                                                         const Eigen::Matrix3d& K,
                                                         const Eigen::Vector2d& start_px,
                                                         const Eigen::Vector2d& end_px);

}  // namespace lvslam::visual
