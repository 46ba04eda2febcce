// LiDAR depth under a pixel: the nearest surface among the samples around
// it, read at the pixel through a local plane.
#include "lvslam/visual/geometry/surface_depth.h"

#include <cmath>

#include <gtest/gtest.h>

namespace lvslam::visual {
namespace {

// A pinhole camera of focal length kF and principal point (kCx, kCy); the
// samples are exact, so a plane's depth at any pixel is known in closed form.
constexpr double kF = 500.0, kCx = 320.0, kCy = 240.0;

// The floor 1 m below the camera (y down): z = f / (v - cy).
double floorDepth(double v) { return kF / (v - kCy); }
// A wall 2 m to the right (x right): z = 2 f / (u - cx).
double wallDepth(double u) { return 2.0 * kF / (u - kCx); }

TEST(SurfaceDepths, TheNearestSurfaceWinsAndNeedsTwoSamples) {
  const std::vector<PixelDepth> samples = {
      {{100.0, 100.0}, 2.0}, {{102.0, 101.0}, 2.0}, {{101.0, 98.0}, 5.0},  // a surface at 2 m, a point behind it
      {{300.0, 300.0}, 3.0},                                               // a lone stray
      {{200.0, 200.0}, 4.0}, {{203.0, 200.0}, 6.0}};                       // two samples, different surfaces
  const auto depths =
      surfaceDepths(samples, {{101.0, 100.0}, {300.0, 301.0}, {201.0, 200.0}, {400.0, 400.0}}, 4.0, 640, 480);
  ASSERT_EQ(depths.size(), 4u);
  EXPECT_NEAR(depths[0], 2.0, 1e-12);  // the point 5 m away is behind the surface
  EXPECT_TRUE(std::isnan(depths[1]));  // one sample is not a surface
  EXPECT_TRUE(std::isnan(depths[2]));  // 6 m is more than 5 % beyond 4 m: an edge
  EXPECT_TRUE(std::isnan(depths[3]));  // nothing near
}

TEST(SurfaceDepths, TheFloorAtAGrazingAngleIsReadAtThePixelNotAtItsNearRing) {
  // Two LiDAR rings cross the floor 10 pixels apart; the pixel lies between them.
  std::vector<PixelDepth> samples;
  for (const double v : {300.0, 310.0})
    for (double u = 312.0; u <= 328.0; u += 2.0) samples.push_back({{u, v}, floorDepth(v)});
  const Eigen::Vector2d pixel(320.0, 305.0);
  const double depth = surfaceDepths(samples, {pixel}, 8.0, 640, 480)[0];
  // The near ring alone reads 7.14 m; the floor under the pixel is 7.69 m away.
  EXPECT_NEAR(depth, floorDepth(pixel.y()), 1e-9);
}

TEST(SurfaceDepths, OneRingAlongASlantedWallGivesTheWallsDepthAtThePixel) {
  // One ring: the samples lie on one image row, the wall's depth changes along it.
  std::vector<PixelDepth> samples;
  for (double u = 400.0; u <= 416.0; u += 2.0) samples.push_back({{u, 240.0}, wallDepth(u)});
  const Eigen::Vector2d pixel(409.0, 243.0);
  // Depth changes by 1.3 % per sample along the ring, 4 % over the radius: one surface.
  const double depth = surfaceDepths(samples, {pixel}, 8.0, 640, 480)[0];
  // Inverse depth is affine along the row: exact at the pixel's column.
  EXPECT_NEAR(depth, wallDepth(pixel.x()), 1e-9);
}

TEST(SurfaceDepths, WhatLiesBehindTheSurfaceIsDroppedUntilTheRestLieOnOnePlane) {
  // A slanted surface from 10 to 11.9 m in steps of 3 % (its far end more than
  // 5 % beyond its near end) and a wall 17 % behind its far end.
  std::vector<PixelDepth> samples;
  double z = 10.0;
  for (double u = 100.0; u <= 106.0; u += 1.0, z *= 1.03) samples.push_back({{u, 100.0}, z});
  samples.push_back({{103.0, 103.0}, 14.0});
  const Eigen::Vector2d pixel(103.0, 100.0);
  const double depth = surfaceDepths(samples, {pixel}, 6.0, 640, 480)[0];
  // Read where the pixel is (10.93 m), between its neighbours on the surface;
  // the samples within 5 % of the nearest alone would say 10.15 m.
  EXPECT_GT(depth, 10.0 * std::pow(1.03, 2));
  EXPECT_LT(depth, 10.0 * std::pow(1.03, 4));
}

TEST(SurfaceDepths, TheRadiusIsAPixelDistance) {
  const std::vector<PixelDepth> samples = {{{10.0, 10.0}, 3.0}, {{10.0, 13.9}, 3.0}, {{10.0, 14.1}, 3.0}};
  // From (10, 10): radius 4 reaches the first two, not the third.
  EXPECT_DOUBLE_EQ(surfaceDepths(samples, {{10.0, 10.0}}, 4.0, 640, 480)[0], 3.0);
  EXPECT_TRUE(std::isnan(surfaceDepths(samples, {{10.0, 6.0}}, 4.0, 640, 480)[0]));  // only the first in reach
  EXPECT_TRUE(std::isnan(surfaceDepths(samples, {{10.0, 10.0}}, 0.0, 640, 480)[0]));
}

TEST(SurfaceDepths, NonFiniteSamplesAndPixelsAreIgnored) {
  const double nan = std::nan("");
  const std::vector<PixelDepth> samples = {
      {{10.0, 10.0}, 3.0}, {{11.0, 10.0}, nan}, {{nan, 10.0}, 3.0}, {{10.0, 11.0}, -1.0}};
  const auto depths = surfaceDepths(samples, {{10.0, 10.0}, {nan, nan}}, 4.0, 640, 480);
  EXPECT_TRUE(std::isnan(depths[0]));  // one usable sample only
  EXPECT_TRUE(std::isnan(depths[1]));
}

}  // namespace
}  // namespace lvslam::visual
