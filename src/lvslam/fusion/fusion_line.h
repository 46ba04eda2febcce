#pragma once
// A 3D line reconstructed from an image segment and LiDAR geometric features
// (paper: "fusion line"), in the camera frame at the camera time.
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace lvslam::fusion {

enum class FusionLineKind : std::uint8_t { kPlaneIntersection, kLinearCluster };

struct ImageSegment {
  Eigen::Vector2d start = Eigen::Vector2d::Zero();  // pixels of the (distorted) image
  Eigen::Vector2d end = Eigen::Vector2d::Zero();
  double length() const { return (end - start).norm(); }
};

struct FusionLine {
  std::size_t segment_index = 0;
  Eigen::Vector3d A = Eigen::Vector3d::Zero();  // endpoints from the segment's end rays
  Eigen::Vector3d B = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  // unit, A to B (d_fu of the paper)
  FusionLineKind kind = FusionLineKind::kPlaneIntersection;
  // The linear LiDAR points that belong to this line (L_s), for the direction
  // feedback d_v_mean; empty in the plane-intersection case.
  std::vector<std::uint64_t> linear_feature_ids;
  int neighbours = 0;
};

enum class RejectReason : std::uint8_t {
  kNone,
  kTooShort,
  kFarOnSphere,       // too few arc samples have a LiDAR neighbour close by
  kMixedShapes,       // neither planar nor linear neighbours are a majority
  kDegenerate,        // grazing plane, line parallel to a ray, ...
  kDepthInconsistent, // neighbours do not lie on the reconstructed line
  kCasesDisagree,     // planar and linear reconstructions differ
  kOutOfRange,
};

}  // namespace lvslam::fusion
