// Ground segmentation (grid of lowest points, a plane per cell) on exact
// synthetic geometry: a tilted floor with small boxes standing on it.
#include "lvslam/lidar/ground_segmentation.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lvslam::lidar {
namespace {

// Floor n . p = d below the sensor, tilted 2.5 deg toward the azimuth 30
// deg: within a 2 m cell it rises 0.12 m at most, inside the 0.15 m height
// threshold, so every floor point of a cell is a candidate.
struct TiltedFloor {
  Eigen::Vector3d n;
  double d = -1.6;
  TiltedFloor() {
    const double tilt = 2.5 * M_PI / 180.0, azimuth = 30.0 * M_PI / 180.0;
    n = Eigen::Vector3d(-std::sin(tilt) * std::cos(azimuth), -std::sin(tilt) * std::sin(azimuth), std::cos(tilt));
  }
  double heightAt(double x, double y) const { return (d - n.x() * x - n.y() * y) / n.z(); }
};

struct Box {
  double x0, y0, size, height;
  bool covers(double x, double y) const { return x >= x0 && x <= x0 + size && y >= y0 && y <= y0 + size; }
};

TimedPoint at(double x, double y, double z) { return {Eigen::Vector3f(x, y, z), 0.0f, -1}; }

struct Scene {
  std::vector<TimedPoint> points;
  std::vector<bool> on_floor;
  void add(const TimedPoint& p, bool floor) {
    points.push_back(p);
    on_floor.push_back(floor);
  }
};

// Floor on a 0.25 m grid over 16 x 16 m, except under the boxes; each box
// (smaller than a cell, so no cell is all box top) with its top and its four
// sides from 0.1 m above the floor, 0.2 m apart along a side: the foot lies
// within the height threshold of the floor but not on it, and is a minority
// of its cell's candidates, as in a scan (at 0.1 m apart, a third of them,
// the first least-squares fit tilts and the refit loses floor points).
Scene floorWithBoxes(const TiltedFloor& floor, const std::vector<Box>& boxes) {
  Scene s;
  for (double x = -8.0; x < 8.0; x += 0.25) {
    for (double y = -8.0; y < 8.0; y += 0.25) {
      bool under_box = false;
      for (const Box& b : boxes) under_box = under_box || b.covers(x, y);
      if (!under_box) s.add(at(x, y, floor.heightAt(x, y)), true);
    }
  }
  for (const Box& b : boxes) {
    const double base = floor.heightAt(b.x0 + b.size / 2, b.y0 + b.size / 2);
    for (double u = 0.0; u <= b.size + 1e-9; u += 0.2) {
      for (double v = 0.0; v <= b.size + 1e-9; v += 0.2) s.add(at(b.x0 + u, b.y0 + v, base + b.height), false);
      for (double h = 0.1; h <= b.height + 1e-9; h += 0.1) {
        s.add(at(b.x0 + u, b.y0, base + h), false);
        s.add(at(b.x0 + u, b.y0 + b.size, base + h), false);
        s.add(at(b.x0, b.y0 + u, base + h), false);
        s.add(at(b.x0 + b.size, b.y0 + u, base + h), false);
      }
    }
  }
  return s;
}

double angleDeg(const Eigen::Vector3f& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.cast<double>().normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 / M_PI;
}

TEST(GroundSegmentation, FloorPointsAreGroundWithTheFloorNormalAndBoxesAreNot) {
  const TiltedFloor floor;
  // Boxes inside cells (0.1 m from their edges) and one across a cell corner.
  const Scene s = floorWithBoxes(floor, {{0.3, 0.3, 0.6, 0.8}, {-5.1, 2.4, 0.5, 0.4}, {3.7, -4.3, 0.6, 1.2}});
  const GroundSegmentation g = segmentGround(s.points, GroundConfig{});
  ASSERT_EQ(g.is_ground.size(), s.points.size());
  ASSERT_EQ(g.normal.size(), s.points.size());
  int floor_points = 0;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    EXPECT_EQ(g.is_ground[i], s.on_floor[i]) << "point " << i << " at " << s.points[i].p.transpose();
    if (!s.on_floor[i]) continue;
    ++floor_points;
    EXPECT_LT(angleDeg(g.normal[i], floor.n), 0.01) << "point " << i;
    EXPECT_GT(g.normal[i].z(), 0.0f);
  }
  EXPECT_GT(floor_points, 4000);
}

TEST(GroundSegmentation, SlopesSteeperThanTheNormalLimitAreNotGround) {
  GroundConfig config;
  config.grid_size = 0.5;  // a 20 deg slope rises 0.18 m in 0.5 m: beyond the height threshold otherwise
  config.height_threshold = 0.5;
  std::vector<TimedPoint> points;
  const double slope = std::tan(20.0 * M_PI / 180.0);  // steeper than max_normal_angle_deg (15)
  for (double x = -4.0; x < 4.0; x += 0.1)
    for (double y = -4.0; y < 4.0; y += 0.1) points.push_back(at(x, y, -2.0 + slope * x));
  const GroundSegmentation g = segmentGround(points, config);
  for (std::size_t i = 0; i < points.size(); ++i) EXPECT_FALSE(g.is_ground[i]) << "point " << i;
}

TEST(GroundSegmentation, NothingAboveTheSensorHeightLimitIsGround) {
  // A level floor at z = -0.2, above max_sensor_height (-0.3): a table top
  // or a ceiling, not the ground under the sensor.
  std::vector<TimedPoint> points;
  for (double x = -3.0; x < 3.0; x += 0.2)
    for (double y = -3.0; y < 3.0; y += 0.2) points.push_back(at(x, y, -0.2));
  const GroundSegmentation g = segmentGround(points, GroundConfig{});
  for (std::size_t i = 0; i < points.size(); ++i) EXPECT_FALSE(g.is_ground[i]);
  EXPECT_TRUE(segmentGround({}, GroundConfig{}).is_ground.empty());
}

}  // namespace
}  // namespace lvslam::lidar
