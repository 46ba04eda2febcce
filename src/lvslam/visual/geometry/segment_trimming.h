#pragma once
// Endpoint trimming of a line landmark (Structure PLP-SLAM, after Zhang et
// al. 2015 / Lee et al. 2019): an infinite 3D line gets the finite extent
// that its observed 2D segments cover. Each observed endpoint is
// back-projected to the point of the line closest to its viewing ray; the
// landmark's endpoints are the outermost of these along the line.
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "lvslam/core/plucker_line.h"

namespace lvslam::visual {

struct SegmentObservation {
  Eigen::Isometry3d T_camera_world = Eigen::Isometry3d::Identity();
  Eigen::Vector2d start = Eigen::Vector2d::Zero(), end = Eigen::Vector2d::Zero();  // undistorted pixels
};

struct TrimmedSegment {
  Eigen::Vector3d start_world, end_world;
};

// None when no observation gives endpoints in front of its camera.
std::optional<TrimmedSegment> trimSegment(const PluckerLine& line_world, const Eigen::Matrix3d& K,
                                          const std::vector<SegmentObservation>& observations);

}  // namespace lvslam::visual
