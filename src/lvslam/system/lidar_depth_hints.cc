#include "lvslam/system/lidar_depth_hints.h"

#include <algorithm>
#include <cmath>

#include "lvslam/core/se3.h"

namespace lvslam::system {

namespace {

// T_image_camera(t) for point times, evaluated once per millisecond: within
// a millisecond a turning robot moves far less than a LiDAR point's noise.
class DeskewCache {
 public:
  DeskewCache(double t_image, double max_dt, const CameraMotion& motion)
      : t_image_(t_image), motion_(motion), poses_(2 * static_cast<std::size_t>(std::ceil(max_dt * 1e3)) + 1) {}

  const Eigen::Isometry3d& T_image_camera(double t) {
    const long half = static_cast<long>(poses_.size() / 2);
    const long bin = std::lround((t - t_image_) * 1e3) + half;
    auto& slot = poses_[static_cast<std::size_t>(std::clamp(bin, 0L, 2 * half))];
    if (!slot) {
      const double t_bin = t_image_ + static_cast<double>(bin - half) * 1e-3;
      slot = interpolateAtTime(t_bin, t_image_, Eigen::Isometry3d::Identity(), motion_.t_other, motion_.T_image_other);
    }
    return *slot;
  }

 private:
  double t_image_;
  CameraMotion motion_;
  std::vector<std::optional<Eigen::Isometry3d>> poses_;
};

}  // namespace

std::vector<visual::PixelDepth> lidarDepthHints(const std::vector<std::shared_ptr<const LidarScan>>& scans,
                                                double t_image, const Calibration& calibration, double max_dt,
                                                const std::optional<CameraMotion>& motion, double min_depth) {
  std::vector<visual::PixelDepth> hints;
  if (!calibration.camera || !(max_dt >= 0.0) || !std::isfinite(max_dt)) return hints;
  const PinholeCamera& camera = *calibration.camera;
  std::optional<DeskewCache> deskew;
  if (motion && motion->t_other != t_image && isRigidTransform(motion->T_image_other))
    deskew.emplace(t_image, max_dt, *motion);
  for (const auto& scan : scans) {
    for (std::size_t i = 0; i < scan->size(); ++i) {
      const double t_point = scan->pointTime(i);
      if (!(std::abs(t_point - t_image) <= max_dt)) continue;
      Eigen::Vector3d p_camera = calibration.T_camera_lidar * scan->points[i].p.cast<double>();
      if (deskew) p_camera = deskew->T_image_camera(t_point) * p_camera;
      if (!(p_camera.z() > min_depth)) continue;  // also drops NaN points
      const auto pixel = camera.project(p_camera);
      if (pixel && camera.inImage(*pixel)) hints.push_back({*pixel, p_camera.z()});
    }
  }
  return hints;
}

}  // namespace lvslam::system
