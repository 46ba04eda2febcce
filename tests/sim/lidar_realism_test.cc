#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "lvslam/sim/camera_renderer.h"
#include "lvslam/sim/families.h"
#include "lvslam/sim/lidar_simulator.h"

namespace lvslam::sim {
namespace {

// VLP-16: 16 rings from -15 to +15 degrees, 2 degrees apart, 1800 columns at
// 10 Hz; each point lies on its ring's cone (noise is along the ray).
TEST(LidarRings, Vlp16HasSixteenRingsTwoDegreesApart) {
  SimOptions options;
  options.scenario = "hall";
  options.lidar = "vlp16";
  options.duration = 5.0;
  const Scenario scenario = makeScenario(options);
  ASSERT_EQ(scenario.lidar.elevations_deg.size(), 16u);
  for (int ring = 0; ring < 16; ++ring) EXPECT_DOUBLE_EQ(scenario.lidar.elevations_deg[ring], -15.0 + 2.0 * ring);
  EXPECT_EQ(scenario.lidar.columns, 1800);
  EXPECT_EQ(scenario.lidar.rate_hz, 10.0);
  const LidarScan scan = LidarSimulator(scenario).scanLidar(2.0);
  std::vector<int> per_ring(16, 0);
  for (const LidarPoint& p : scan.points) {
    ASSERT_LT(p.ring, 16);
    ++per_ring[p.ring];
    const double elevation = std::asin(p.p.z() / p.p.norm()) * 180.0 / M_PI;
    EXPECT_NEAR(elevation, -15.0 + 2.0 * p.ring, 1e-3);
  }
  for (int ring = 0; ring < 16; ++ring) EXPECT_GT(per_ring[ring], 1000) << "ring " << ring;
  EXPECT_LE(scan.size(), 16u * 1800u);
}

// In the glass family's atrium: where the camera's ray meets a pane first, the
// rendered depth lies behind the pane (the camera sees through it), and no
// LiDAR point lies on a pane; a share of about glass_return of the pulses
// that meet a pane return from behind it. The LiDAR is exact here (rays, no
// range noise) so that "on a pane" is exact too; footprints: LidarBeam tests.
TEST(LidarRealism, GlassPaneGivesNoReturnWhereTheCameraSeesThrough) {
  SimOptions options = familyOptions("glass");
  options.duration = 5.0;
  Scenario scenario = makeScenario(options);
  scenario.lidar.beam.footprint = false;
  scenario.lidar.range_noise = scenario.lidar.range_noise_per_metre = 0.0;
  const World& world = scenario.world;
  const double t = 2.0;
  const auto isGlass = [&](const std::optional<WorldHit>& hit) {
    return hit && hit->primitive >= 0 && world.primitives()[hit->primitive].glass;
  };
  // Camera.
  const cv::Mat depth = CameraRenderer(scenario).renderDepth(t);
  const Eigen::Isometry3d T_world_camera = scenario.T_world_camera(t);
  int through = 0;
  for (int y = 0; y < depth.rows; y += 8)
    for (int x = 0; x < depth.cols; x += 8) {
      const Eigen::Vector3d ray = scenario.camera.camera.unproject(Eigen::Vector2d(x, y));
      const auto hit = world.raycast(T_world_camera.translation(), T_world_camera.linear() * ray);
      if (!isGlass(hit)) continue;
      ++through;
      const float z = depth.at<float>(y, x);
      const double pane_z = hit->distance * ray.normalized().z();
      EXPECT_TRUE(z == 0.0f || z > pane_z + 0.05) << "pixel " << x << ", " << y;
    }
  EXPECT_GT(through, 500);
  // LiDAR: every column and ring as the simulator fires them.
  const LidarScan scan = LidarSimulator(scenario).scanLidar(t);
  const LidarConfig& config = scenario.lidar;
  int pulses_on_glass = 0;  // with a surface behind the pane in range
  for (int c = 0; c < config.columns; ++c) {
    const double time = c / (config.rate_hz * config.columns);
    const Eigen::Isometry3d T_world_lidar = scenario.T_world_lidar(t + time);
    for (const double elevation_deg : config.elevations_deg) {
      const double e = elevation_deg * M_PI / 180.0, a = M_PI - 2.0 * M_PI * c / config.columns;
      const Eigen::Vector3d dir(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
      const Eigen::Vector3d origin = T_world_lidar.translation(), dir_world = T_world_lidar.linear() * dir;
      if (isGlass(world.raycast(origin, dir_world, 101.0)) && world.raycast(origin, dir_world, 100.0, 0.0, true))
        ++pulses_on_glass;
    }
  }
  const auto on = [&](const Eigen::Vector3d& p, bool glass) {
    for (const Primitive& primitive : world.primitives())
      if (primitive.glass == glass && distanceToSurface(primitive, p) < 1e-4) return true;
    return false;
  };
  int behind = 0;
  for (std::size_t k = 0; k < scan.size(); ++k) {
    const Eigen::Isometry3d T_world_lidar = scenario.T_world_lidar(scan.pointTime(k));
    const Eigen::Vector3d p = T_world_lidar * scan.points[k].p.cast<double>();
    EXPECT_FALSE(on(p, true) && !on(p, false)) << "a point on a pane at " << p.transpose();
    const Eigen::Vector3d origin = T_world_lidar.translation();
    if (isGlass(world.raycast(origin, p - origin, 101.0))) ++behind;
  }
  EXPECT_GT(pulses_on_glass, 5000);
  const double share = static_cast<double>(behind) / pulses_on_glass;
  std::cout << pulses_on_glass << " pulses meet glass, " << behind << " return from behind (" << share << ")\n";
  // Less the dropouts (1 % and more at grazing incidence).
  EXPECT_GT(share, 0.8 * config.beam.glass_return);
  EXPECT_LT(share, config.beam.glass_return);
}

}  // namespace
}  // namespace lvslam::sim
