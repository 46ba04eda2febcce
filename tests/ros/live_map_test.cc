// The node's display map and latency figures (ROS-free parts of ros/).
#include <gtest/gtest.h>

#include "live_map.h"
#include "publish_latency.h"

namespace lvslam::ros_node {
namespace {

LidarScan wall(double t) {
  LidarScan scan;
  scan.timestamp = t;
  for (int i = 0; i < 100; ++i) {  // 1 m of wall at x = 5, points 1 cm apart
    LidarPoint p;
    p.p = Eigen::Vector3f(5.0f, 0.01f * static_cast<float>(i), 0.0f);
    scan.points.push_back(p);
  }
  return scan;
}

Eigen::Isometry3d at(double x) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation().x() = x;
  return T;
}

TEST(LiveMap, PlacesASweepByThePoseAfterItsStampOnePointPerVoxel) {
  LiveMapOptions options;
  options.voxel_m = 0.2;
  LiveMap map(options, Eigen::Isometry3d::Identity());
  map.addScan(wall(1.0));
  EXPECT_EQ(map.size(), 0u);  // no pose yet
  map.addPose(1.05, at(2.0));
  const std::vector<Eigen::Vector3f> points = map.points();
  ASSERT_EQ(points.size(), 5u);  // 1 m of wall in 0.2 m voxels
  for (const Eigen::Vector3f& p : points) EXPECT_FLOAT_EQ(p.x(), 7.0f);
}

TEST(LiveMap, AddsASweepOnlyOnceTheRobotHasMoved) {
  LiveMapOptions options;
  options.min_step_m = 0.5;
  LiveMap map(options, Eigen::Isometry3d::Identity());
  map.addScan(wall(1.0));
  map.addPose(1.0, at(0.0));
  const std::size_t first = map.size();
  map.addScan(wall(2.0));
  map.addPose(2.0, at(0.1));  // 10 cm: not added
  EXPECT_EQ(map.size(), first);
  map.addScan(wall(3.0));
  map.addPose(3.0, at(1.0));  // 1 m: added, where the wall now is
  EXPECT_EQ(map.size(), 2 * first);
}

TEST(PublishLatency, MeasuresArrivalToPublicationAndIgnoresAForeignClock) {
  PublishLatency latency;
  const auto t0 = PublishLatency::Clock::now();
  for (int i = 0; i < 10; ++i) {
    const double stamp = 100.0 + i;
    latency.arrived(stamp, t0 + std::chrono::seconds(i));
    latency.published(stamp, t0 + std::chrono::seconds(i) + std::chrono::milliseconds(10 * (i + 1)), stamp + 0.05);
  }
  latency.published(200.0, t0, 1e9);  // never arrived, and a clock that is not the data's
  const LatencySummary s = latency.summary();
  EXPECT_EQ(s.frames, 10u);
  EXPECT_NEAR(s.arrival_median_ms, 60.0, 1e-6);
  EXPECT_NEAR(s.arrival_p95_ms, 100.0, 1e-6);
  EXPECT_EQ(s.stamp_frames, 10u);
  EXPECT_NEAR(s.stamp_median_ms, 50.0, 1e-6);
}

}  // namespace
}  // namespace lvslam::ros_node
