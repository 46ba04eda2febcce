#pragma once
// The fusion framework of the paper, one camera frame at a time: LiDAR
// features of the last scans aligned to the camera time and frame, image line
// segments associated with them on the sphere, fusion lines reconstructed and
// the feedback for both subsystems (fusion lines for the visual subsystem,
// mean directions d_v_mean for the LiDAR's linear points, LiDAR depth for
// image points).
#include <array>
#include <vector>

#include "lvslam/core/camera.h"
#include "lvslam/fusion/feature_accumulator.h"
#include "lvslam/fusion/fusion_config.h"
#include "lvslam/fusion/fusion_line.h"
#include "lvslam/fusion/line_reconstruction.h"

namespace lvslam::fusion {

// The linear LiDAR points L_s behind one fusion line and their new common
// direction d_v_mean, in the world frame the LiDAR subsystem works in.
struct LinearDirectionUpdate {
  std::vector<std::uint64_t> ids;
  Eigen::Vector3d direction_world = Eigen::Vector3d::UnitX();
};

struct FusionResult {
  double t_camera = 0.0;
  std::vector<FusionLine> lines;  // camera frame at t_camera
  std::vector<LinearDirectionUpdate> lidar_updates;
  std::array<int, 8> rejected{};  // count per RejectReason
  std::size_t lidar_features = 0;
};

class FusionFramework {
 public:
  FusionFramework(const PinholeCamera& camera, const Eigen::Isometry3d& T_camera_lidar, const FusionConfig& config);

  // Classified feature points of one LiDAR scan with the scan's motion.
  void addLidarScan(const std::vector<TimedFeature>& features, const ConstantVelocityMotion& motion);
  // Forgets the accumulated scans (a driver that reloads them each scan).
  void clearLidarScans() { accumulator_.clear(); }
  std::size_t accumulatedScans() const { return accumulator_.scans(); }

  // One camera frame: `T_world_lidar` is the LiDAR pose at the camera time
  // (interpolated or extrapolated at constant velocity by the caller).
  FusionResult process(double t_camera, const Eigen::Isometry3d& T_world_lidar,
                       const std::vector<ImageSegment>& segments) const;

  // Camera-frame depth (z) of the LiDAR surface under each pixel, NaN where
  // no consistent LiDAR feature projects within max_pixel_distance.
  std::vector<double> pointDepths(const Eigen::Isometry3d& T_world_lidar, const std::vector<Eigen::Vector2d>& pixels,
                                  double max_pixel_distance) const;

  // The accumulated features in the camera frame (for debug images).
  std::vector<SphereFeature> featuresInCamera(const Eigen::Isometry3d& T_world_lidar) const;

  const PinholeCamera& camera() const { return camera_; }
  const Eigen::Isometry3d& T_camera_lidar() const { return T_camera_lidar_; }

 private:
  PinholeCamera camera_;
  Eigen::Isometry3d T_camera_lidar_;
  FusionConfig config_;
  FeatureAccumulator accumulator_;
  LineReconstructor reconstructor_;
};

}  // namespace lvslam::fusion
