#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include <gtest/gtest.h>

#include "lvslam/core/se3.h"
#include "lvslam/io/sequence_reader.h"
#include "lvslam/io/tum.h"
#include "lvslam/sim/camera_renderer.h"
#include "lvslam/sim/lidar_simulator.h"
#include "lvslam/sim/simulate_sequence.h"
#include "support/temp_dir.h"

namespace lvslam::sim {
namespace {

// Ground-truth pose at t, interpolated between the two written poses around it.
Eigen::Isometry3d poseAt(const Trajectory& gt, double t) {
  auto it = std::lower_bound(gt.begin(), gt.end(), t, [](const StampedPose& p, double x) { return p.t < x; });
  if (it == gt.begin()) ++it;
  if (it == gt.end()) --it;
  const StampedPose& a = *(it - 1);
  return interpolateAtTime(t, a.t, a.T_world_frame, it->t, it->T_world_frame);
}

double meanDistance(const World& world, const std::vector<Eigen::Vector3d>& points) {
  double sum = 0.0;
  for (const auto& p : points) sum += world.distanceToSurface(p);
  return sum / static_cast<double>(points.size());
}

// Scan points moved into the world with the written ground truth at each
// point's own time lie on the analytic surfaces (within the range noise).
TEST(LidarTruth, WrittenScansLieOnSurfacesAtTheirOwnTimes) {
  testing::TempDir dir;
  SimOptions options;
  options.scenario = "hall";
  options.duration = 0.5;
  simulateSequence(options, dir.path().string());
  const SequenceReader reader(dir.path().string());
  const Trajectory gt = readTum(dir.file("groundtruth.txt"));
  const Scenario scenario = makeScenario(options);
  const Eigen::Isometry3d T_camera_lidar = reader.info().T_camera_lidar;
  ASSERT_GE(reader.lidarFiles().size(), 3u);
  for (std::size_t i = 0; i < reader.lidarFiles().size(); ++i) {
    const LidarScan scan = reader.loadScan(i);
    ASSERT_GT(scan.size(), 30000u);
    std::vector<Eigen::Vector3d> world_points;
    for (std::size_t k = 0; k < scan.size(); k += 7)
      world_points.push_back(poseAt(gt, scan.pointTime(k)) * T_camera_lidar * scan.points[k].p.cast<double>());
    const double mean = meanDistance(scenario.world, world_points);
    std::cout << "scan " << i << ": mean distance to the surfaces " << mean << " m\n";
    EXPECT_LT(mean, 1.5 * scenario.lidar.range_noise) << "scan " << i;
  }
}

// The same with the robot at full speed: per-point poses fit, while one pose
// for the whole sweep (ignoring the motion distortion) does not.
TEST(LidarTruth, ScansAreMotionDistortedLikeARealSweep) {
  SimOptions options;
  options.scenario = "hall";
  options.duration = 30.0;
  const Scenario scenario = makeScenario(options);
  ASSERT_GT(scenario.trajectory.speedAt(20.0), 0.5);
  const LidarScan scan = LidarSimulator(scenario).scanLidar(20.0);
  std::vector<Eigen::Vector3d> own_time, start_time;
  for (std::size_t k = 0; k < scan.size(); k += 5) {
    const Eigen::Vector3d p = scan.points[k].p.cast<double>();
    own_time.push_back(scenario.T_world_lidar(scan.pointTime(k)) * p);
    start_time.push_back(scenario.T_world_lidar(scan.timestamp) * p);
  }
  const double own = meanDistance(scenario.world, own_time), skewed = meanDistance(scenario.world, start_time);
  std::cout << "per-point poses: " << own << " m, one pose per sweep: " << skewed << " m\n";
  EXPECT_LT(own, 1.5 * scenario.lidar.range_noise);
  EXPECT_GT(skewed, 2.0 * own);
  // Real sensor output: 32 rings, times within one sweep, no point at the origin.
  for (const LidarPoint& p : scan.points) {
    ASSERT_LT(p.ring, 32);
    ASSERT_GE(p.time, 0.0f);
    ASSERT_LT(p.time, 0.1f);
    ASSERT_GT(p.p.norm(), 0.4f);
  }
}

// LiDAR points deskewed to an image's time and projected with the true
// extrinsics land where the rendered depth says.
TEST(LidarTruth, DeskewedPointsAgreeWithRenderedDepth) {
  SimOptions options;
  options.duration = 20.0;
  const Scenario scenario = makeScenario(options);
  const double t_scan = 10.0, t_image = 10.05;
  const LidarScan scan = LidarSimulator(scenario).scanLidar(t_scan);
  const cv::Mat depth = CameraRenderer(scenario).renderDepth(t_image);
  const Eigen::Isometry3d T_lidar_world = scenario.T_world_lidar(t_image).inverse();
  const Eigen::Isometry3d T_camera_lidar = scenario.rig.T_camera_lidar();
  const PinholeCamera& camera = scenario.camera.camera;
  std::vector<double> differences;
  for (std::size_t k = 0; k < scan.size(); ++k) {
    // Deskew: the point in the LiDAR frame at the image time, then into the camera.
    const Eigen::Vector3d p_lidar =
        T_lidar_world * scenario.T_world_lidar(scan.pointTime(k)) * scan.points[k].p.cast<double>();
    const Eigen::Vector3d p_camera = T_camera_lidar * p_lidar;
    const auto pixel = camera.project(p_camera);
    if (!pixel || !camera.inImage(*pixel, 1.0)) continue;
    const float z = depth.at<float>(static_cast<int>(std::lround(pixel->y())), static_cast<int>(std::lround(pixel->x())));
    differences.push_back(std::abs(z - p_camera.z()));
  }
  ASSERT_GT(differences.size(), 3000u);
  std::nth_element(differences.begin(), differences.begin() + differences.size() / 2, differences.end());
  std::cout << differences.size() << " points in the image, median |depth difference| "
            << differences[differences.size() / 2] << " m\n";
  EXPECT_LT(differences[differences.size() / 2], 0.03);
}

// A walking person is seen by the LiDAR where the person is at each point's
// own time: those points lie on the moving box, not on the static world.
TEST(LidarTruth, WalkingPersonIsWhereItWalksAtEachPointsTime) {
  SimOptions options;
  options.walking_person = true;
  options.duration = 20.0;
  const Scenario scenario = makeScenario(options);
  ASSERT_EQ(scenario.people.size(), 1u);
  const LidarSimulator lidar(scenario);
  int on_person = 0;
  for (const double t : {3.0, 8.0, 13.0}) {
    const LidarScan scan = lidar.scanLidar(t);
    for (std::size_t k = 0; k < scan.size(); ++k) {
      const Eigen::Vector3d p = scenario.T_world_lidar(scan.pointTime(k)) * scan.points[k].p.cast<double>();
      const double to_person = distanceToSurface(scenario.people[0].at(scan.pointTime(k)), p);
      const double to_world = scenario.world.distanceToSurface(p);
      EXPECT_LT(std::min(to_person, to_world), 0.1);
      if (to_person < 0.05 && to_world > 0.2) ++on_person;
    }
  }
  EXPECT_GT(on_person, 50);
}

}  // namespace
}  // namespace lvslam::sim
