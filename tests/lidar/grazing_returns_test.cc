#include "lvslam/lidar/grazing_returns.h"

#include <cmath>

#include <gtest/gtest.h>

namespace lvslam::lidar {
namespace {

constexpr double kStepRad = 0.2 * M_PI / 180.0;  // a VLP-32C's azimuth step at 10 Hz

TimedPoint atAzimuth(double range, double azimuth_rad, int ring) {
  return {Eigen::Vector3f(static_cast<float>(range * std::cos(azimuth_rad)), static_cast<float>(range * std::sin(azimuth_rad)), 0.0f),
          0.0f, ring};
}

// One ring sweeping a wall parallel to the x axis at y = wall_y, from
// azimuth first_rad on in kStepRad steps (range wall_y / sin(azimuth)).
std::vector<TimedPoint> ringAlongWall(double wall_y, double first_rad, int count, int ring) {
  std::vector<TimedPoint> points;
  for (int k = 0; k < count; ++k) {
    const double azimuth = first_rad + k * kStepRad;
    points.push_back(atAzimuth(wall_y / std::sin(azimuth), azimuth, ring));
  }
  return points;
}

TEST(GrazingReturns, AWallIsGrazingExactlyWhereBothRingNeighboursAreFartherThanTheRadiusAndItRecedes) {
  // Far ahead (azimuth 2 deg: 57 m, neighbours 1.7 m apart) to the side
  // (azimuth 80 deg: 2 m, 7 mm apart).
  const std::vector<TimedPoint> points = ringAlongWall(2.0, 2.0 * M_PI / 180.0, 390, 7);
  const double radius = 1.0;
  const std::vector<bool> grazing = grazingReturns(points, radius);
  ASSERT_EQ(grazing.size(), points.size());
  int count = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    // The ring wraps: the first return's other neighbour is the last one, nearer
    // like its next one, so the first return (a range maximum) is not grazing.
    const Eigen::Vector3f& before = points[k == 0 ? points.size() - 1 : k - 1].p;
    const Eigen::Vector3f& after = points[(k + 1) % points.size()].p;
    const bool far = (before - points[k].p).norm() > radius && (after - points[k].p).norm() > radius;
    EXPECT_EQ(grazing[k], far && k > 0) << "return " << k;
    count += grazing[k] ? 1 : 0;
  }
  // The spacing 2 step / sin^2(az) falls below 1 m at az = asin(sqrt(2 step)).
  const double last_grazing_deg = std::asin(std::sqrt(2.0 * kStepRad)) * 180.0 / M_PI;
  EXPECT_NEAR(count, (last_grazing_deg - 2.0) / 0.2 - 1.0, 1.0);
}

TEST(GrazingReturns, AThinPoleInFrontOfTheBackgroundIsNotGrazing) {
  // Background 40 m away all around, a one-column pole at 20 m (azimuth 0)
  // and one column seen through a gap at 60 m (azimuth 90 deg).
  std::vector<TimedPoint> points;
  for (int k = 0; k < 1800; ++k) {
    const double azimuth_deg = -180.0 + 0.2 * k;
    const double range = std::abs(azimuth_deg) < 0.1 ? 20.0 : std::abs(azimuth_deg - 90.0) < 0.1 ? 60.0 : 40.0;
    points.push_back(atAzimuth(range, azimuth_deg * M_PI / 180.0, 3));
  }
  const std::vector<bool> grazing = grazingReturns(points, 1.0);
  for (std::size_t k = 0; k < points.size(); ++k) EXPECT_FALSE(grazing[k]) << "return " << k;
}

TEST(GrazingReturns, ReturnsWithoutARingAreNeverGrazingAndRingsDoNotMix) {
  std::vector<TimedPoint> points = ringAlongWall(2.0, 2.0 * M_PI / 180.0, 3, -1);  // far apart, no ring
  // Ring 1 recedes through its middle return; ring 2's returns lie close
  // to ring 1's, which must not count as neighbours.
  for (const double range : {40.0, 45.0, 50.0}) points.push_back(atAzimuth(range, range / 1000.0, 1));
  points.push_back(atAzimuth(45.0, 0.0451, 2));
  const std::vector<bool> grazing = grazingReturns(points, 1.0);
  EXPECT_EQ(grazing, (std::vector<bool>{false, false, false, false, true, false, false}));
}

}  // namespace
}  // namespace lvslam::lidar
