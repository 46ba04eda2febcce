#pragma once
// What the fusion framework knows of a LiDAR geometric feature point once it
// is aligned to the camera time and frame.
#include <cstdint>

#include <Eigen/Core>

namespace lvslam::fusion {

enum class FeatureShape : std::uint8_t { kPlanar, kLinear, kOther };

struct SphereFeature {
  Eigen::Vector3d p_camera = Eigen::Vector3d::Zero();
  // Unit normal for planar points, unit line direction for linear points.
  Eigen::Vector3d direction_camera = Eigen::Vector3d::UnitZ();
  FeatureShape shape = FeatureShape::kOther;
  std::uint64_t id = 0;  // the LiDAR subsystem's handle, for the direction feedback
};

}  // namespace lvslam::fusion
