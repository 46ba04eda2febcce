#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "lvslam/sim/camera_renderer.h"
#include "lvslam/sim/lidar_simulator.h"

namespace lvslam::sim {
namespace {

Scenario crowdedHall() {
  SimOptions options;
  options.scenario = "hall";
  options.people = 8;
  options.duration = 20.0;
  return makeScenario(options);
}

// Each person walks out and back along its own segment at its own speed:
// at `from` when the distance walked (speed t + phase) is a multiple of
// twice the length, at `to` half a period later, half way between at a quarter.
TEST(People, WalkAsTheirPathsSay) {
  const Scenario scenario = crowdedHall();
  ASSERT_EQ(scenario.people.size(), 8u);
  std::set<double> speeds;
  for (const WalkingPerson& person : scenario.people) {
    const double length = (person.to - person.from).norm();
    ASSERT_GT(length, 4.99);
    speeds.insert(person.speed);
    const double t0 = (2.0 * length - person.phase) / person.speed;
    const auto xy = [&](double t) { return Eigen::Vector2d(person.at(t).center.head<2>()); };
    EXPECT_LT((xy(t0) - person.from).norm(), 1e-6);
    EXPECT_LT((xy(t0 + length / person.speed) - person.to).norm(), 1e-6);
    EXPECT_LT((xy(t0 + 0.5 * length / person.speed) - 0.5 * (person.from + person.to)).norm(), 1e-6);
    EXPECT_LT((xy(t0 + 1.5 * length / person.speed) - 0.5 * (person.from + person.to)).norm(), 1e-6);
    EXPECT_NEAR(person.at(t0).center.z(), 0.5 * person.size.z(), 1e-12);  // standing on the floor
  }
  EXPECT_EQ(speeds.size(), 8u);  // each at its own pace
}

// The LiDAR and the camera both see several of the people, where they are at
// each point's or pixel's own time.
TEST(People, BothSensorsSeeThem) {
  const Scenario scenario = crowdedHall();
  Scenario empty = scenario;
  empty.people.clear();
  std::set<int> seen_by_lidar, seen_by_camera;
  const LidarSimulator lidar(scenario);
  for (const double t : {4.0, 9.0, 14.0}) {
    const LidarScan scan = lidar.scanLidar(t);
    for (std::size_t k = 0; k < scan.size(); ++k) {
      const double tk = scan.pointTime(k);
      const Eigen::Vector3d p = scenario.T_world_lidar(tk) * scan.points[k].p.cast<double>();
      for (std::size_t i = 0; i < scenario.people.size(); ++i)
        if (distanceToSurface(scenario.people[i].at(tk), p) < 0.05 && scenario.world.distanceToSurface(p) > 0.2)
          seen_by_lidar.insert(static_cast<int>(i));
    }
    const cv::Mat depth = CameraRenderer(scenario).renderDepth(t);
    const cv::Mat background = CameraRenderer(empty).renderDepth(t);
    const Eigen::Isometry3d T_world_camera = scenario.T_world_camera(t);
    const PinholeCamera& camera = scenario.camera.camera;
    for (int y = 0; y < depth.rows; y += 4)
      for (int x = 0; x < depth.cols; x += 4) {
        const float z = depth.at<float>(y, x);
        if (!(z < background.at<float>(y, x) - 0.05f)) continue;  // something in front of the static world
        const Eigen::Vector3d ray = camera.unproject(Eigen::Vector2d(x, y));
        const Eigen::Vector3d p = T_world_camera * (ray / ray.z() * z);
        int on = -1;
        for (std::size_t i = 0; i < scenario.people.size(); ++i)
          if (distanceToSurface(scenario.people[i].at(t), p) < 1e-3) on = static_cast<int>(i);
        ASSERT_GE(on, 0) << "pixel " << x << ", " << y << " in front of the world but on nobody";
        seen_by_camera.insert(on);
      }
  }
  EXPECT_GE(seen_by_lidar.size(), 5u);
  EXPECT_GE(seen_by_camera.size(), 2u);
}

}  // namespace
}  // namespace lvslam::sim
