#include "lvslam/fusion/lidar_depth_hints.h"

#include <cmath>

namespace lvslam::fusion {

std::vector<visual::PixelDepth> lidarDepthHints(const std::vector<std::shared_ptr<const LidarScan>>& scans,
                                                double t_image, const Calibration& calibration, double max_dt,
                                                double min_depth) {
  std::vector<visual::PixelDepth> hints;
  if (!calibration.camera) return hints;
  const PinholeCamera& camera = *calibration.camera;
  for (const auto& scan : scans) {
    for (std::size_t i = 0; i < scan->size(); ++i) {
      if (!(std::abs(scan->pointTime(i) - t_image) <= max_dt)) continue;
      const Eigen::Vector3d p_camera = calibration.T_camera_lidar * scan->points[i].p.cast<double>();
      if (!(p_camera.z() > min_depth)) continue;  // also drops NaN points
      const auto pixel = camera.project(p_camera);
      if (pixel && camera.inImage(*pixel)) hints.push_back({*pixel, p_camera.z()});
    }
  }
  return hints;
}

}  // namespace lvslam::fusion
