// LiDAR depth for image points: raw points of a sweep taken while the camera
// moves, deskewed with the camera's own motion, against the exact depth of a
// known wall at the image time.
#include "lvslam/system/lidar_depth_hints.h"

#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "lvslam/core/se3.h"
#include "fusion/test_rig.h"

namespace lvslam::system {
namespace {

// The test rig (test_rig.h): f = 400 px, principal point (320, 240).
Calibration rig() {
  Calibration c;
  c.camera = fusion::testing::testCamera();
  c.T_camera_lidar = fusion::testing::cameraFromLidar();
  return c;
}

// The camera drives forward (its z) at 1 m/s and yaws at 0.5 rad/s (a turn).
Eigen::Isometry3d T_world_camera(double t) {
  return makePose(expSO3(Eigen::Vector3d(0.0, 0.5 * t, 0.0)), Eigen::Vector3d(0.0, 0.0, t));
}

constexpr double kWallZ = 4.0;  // the wall z = 4 m in the world

// A sweep from t0 to t0 + 0.1 s of the wall: a grid of directions, each
// measured at its own time in the LiDAR frame of that time.
std::shared_ptr<const LidarScan> sweepOfTheWall(double t0) {
  auto scan = std::make_shared<LidarScan>();
  scan->timestamp = t0;
  scan->has_time = true;
  const Calibration c = rig();
  const Eigen::Isometry3d T_lidar_camera = c.T_camera_lidar.inverse();
  const int n = 4000;
  for (int i = 0; i < n; ++i) {
    const double s = static_cast<double>(i) / n;
    const double t = t0 + 0.1 * s;
    // Rays over the image: columns follow time (a rotating head), rows interleave.
    const Eigen::Vector3d ray_camera(-0.7 + 1.4 * s, -0.5 + 1.0 * ((i * 37) % 101) / 100.0, 1.0);
    const Eigen::Isometry3d T_wc = T_world_camera(t);
    const Eigen::Vector3d dir_world = T_wc.linear() * ray_camera;
    const double range = (kWallZ - T_wc.translation().z()) / dir_world.z();
    if (!(range > 0.0)) continue;
    const Eigen::Vector3d p_camera = range * ray_camera;
    LidarPoint point;
    point.p = (T_lidar_camera * p_camera).cast<float>();
    point.time = static_cast<float>(t - t0);
    scan->points.push_back(point);
  }
  return scan;
}

// Depth of the wall, at time t, along the ray of a pixel.
double trueDepth(double t, const Eigen::Vector2d& pixel) {
  const Eigen::Vector3d ray((pixel.x() - 320.0) / 400.0, (pixel.y() - 240.0) / 400.0, 1.0);
  const Eigen::Isometry3d T_wc = T_world_camera(t);
  return (kWallZ - T_wc.translation().z()) / (T_wc.linear() * ray).z();  // ray has z = 1: this is the depth
}

double worstRelativeError(const std::vector<visual::PixelDepth>& hints, double t_image) {
  double worst = 0.0;
  for (const visual::PixelDepth& h : hints)
    worst = std::max(worst, std::abs(h.depth - trueDepth(t_image, h.pixel)) / trueDepth(t_image, h.pixel));
  return worst;
}

TEST(LidarDepthHints, CameraMotionDeskewsAWholeSweep) {
  const double t_image = 0.08;
  const std::vector<std::shared_ptr<const LidarScan>> scans = {sweepOfTheWall(0.0)};
  // The previous frame at 15 Hz, seen from the image's camera.
  const double t_previous = t_image - 1.0 / 15.0;
  const CameraMotion motion{t_previous, T_world_camera(t_image).inverse() * T_world_camera(t_previous)};

  const auto deskewed = lidarDepthHints(scans, t_image, rig(), 0.1, motion);
  ASSERT_GT(deskewed.size(), 1000u);
  // Constant velocity is exact here up to the 1 ms time bins: a 0.5 rad/s
  // turn moves a bearing by 0.25 mrad within half a bin.
  EXPECT_LT(worstRelativeError(deskewed, t_image), 1e-3);

  // Without the motion the same window is off by the robot's travel (up to
  // 8 cm of 3-4 m) and the turn.
  const auto raw = lidarDepthHints(scans, t_image, rig(), 0.1);
  ASSERT_GT(raw.size(), 1000u);
  EXPECT_GT(worstRelativeError(raw, t_image), 0.02);
}

TEST(LidarDepthHints, TheTimeWindowKeepsOnlyPointsNearTheImage) {
  const std::vector<std::shared_ptr<const LidarScan>> scans = {sweepOfTheWall(0.0)};
  const auto near = lidarDepthHints(scans, 0.05, rig(), 0.01);
  const auto all = lidarDepthHints(scans, 0.05, rig(), 0.1);
  ASSERT_FALSE(near.empty());
  // A fifth of the sweep's 0.1 s, up to the points that miss the image.
  EXPECT_NEAR(static_cast<double>(near.size()) / static_cast<double>(all.size()), 0.2, 0.05);
  // Measured within 10 ms of the image: the error stays within that motion.
  EXPECT_LT(worstRelativeError(near, 0.05), 0.01);
}

TEST(LidarDepthHints, NaNPointsAndPointsBehindTheCameraGiveNoHint) {
  auto scan = std::make_shared<LidarScan>();
  scan->timestamp = 0.0;
  LidarPoint nan_point;
  nan_point.p = Eigen::Vector3f::Constant(std::nanf(""));
  LidarPoint behind;
  behind.p = Eigen::Vector3f(-3.0f, 0.0f, 0.0f);  // behind the LiDAR, so behind the camera
  scan->points = {nan_point, behind};
  EXPECT_TRUE(lidarDepthHints({scan}, 0.0, rig(), 0.1).empty());
  EXPECT_TRUE(lidarDepthHints({scan}, 0.0, rig(), 0.1, CameraMotion{-0.05, Eigen::Isometry3d::Identity()}).empty());
}

}  // namespace
}  // namespace lvslam::system
