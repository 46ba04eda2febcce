// Deskew undoes a known constant-velocity motion exactly.
#include <gtest/gtest.h>

#include "lidar/synthetic_lidar.h"
#include "lvslam/lidar/deskew.h"

namespace lvslam::lidar {
namespace {

struct DeskewCase {
  Vector6d velocity;
  Eigen::Isometry3d T_world_start;
  LidarScan scan;
  std::vector<Eigen::Vector3d> world_hits;
};

DeskewCase movingSensor() {
  DeskewCase c;
  c.velocity << 1.5, 0.2, 0.05, 0.02, -0.03, 0.8;  // m/s and rad/s: a fast turn
  c.T_world_start = makePose(Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ())),
                             Eigen::Vector3d(-3, 1, 1));
  testing::SyntheticSensor sensor;
  sensor.columns = 360;
  c.scan = testing::castScan(
      testing::structuredRoom(), [&](double t) { return c.T_world_start * motionOver(c.velocity, t); }, 0.0, sensor,
      nullptr, &c.world_hits);
  return c;
}

std::vector<TimedPoint> timedPoints(const LidarScan& scan) {
  std::vector<TimedPoint> points;
  for (const LidarPoint& p : scan.points) points.push_back({p.p, p.time, p.ring});
  return points;
}

double largestError(const std::vector<TimedPoint>& points, const DeskewCase& c) {
  double largest = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d expected = c.T_world_start.inverse() * c.world_hits[i];
    largest = std::max(largest, (points[i].p.cast<double>() - expected).norm());
  }
  return largest;
}

TEST(Deskew, MovesEveryPointToTheReferenceTime) {
  const DeskewCase c = movingSensor();
  std::vector<TimedPoint> points = timedPoints(c.scan);
  ASSERT_GT(points.size(), 5000u);
  EXPECT_GT(largestError(points, c), 0.1);  // the raw sweep is visibly skewed
  deskewToReference(points, c.velocity);
  EXPECT_LT(largestError(points, c), 1e-4);
}

TEST(Deskew, VelocityBetweenTwoPosesIsTheTwistPerSecond) {
  const DeskewCase c = movingSensor();
  const Eigen::Isometry3d T_later = c.T_world_start * motionOver(c.velocity, 0.1);
  const Vector6d v = velocityBetween(c.T_world_start, 5.0, T_later, 5.1);
  EXPECT_LT((v - c.velocity).norm(), 1e-9);
  EXPECT_TRUE(velocityBetween(c.T_world_start, 5.0, T_later, 5.0).isZero());  // no time: no velocity
}

}  // namespace
}  // namespace lvslam::lidar
