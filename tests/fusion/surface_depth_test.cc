// LiDAR depth under a pixel: the nearest surface among the samples around it.
#include "lvslam/fusion/surface_depth.h"

#include <cmath>

#include <gtest/gtest.h>

namespace lvslam::fusion {
namespace {

TEST(SurfaceDepths, TheNearestSurfaceWinsAndNeedsTwoSamples) {
  const std::vector<visual::PixelDepth> samples = {
      {{100.0, 100.0}, 2.00}, {{102.0, 101.0}, 2.04}, {{101.0, 98.0}, 5.0},  // a surface at 2 m, a point behind it
      {{300.0, 300.0}, 3.0},                                                 // a lone stray
      {{200.0, 200.0}, 4.0}, {{203.0, 200.0}, 6.0}};                         // two samples, different surfaces
  const auto depths =
      surfaceDepths(samples, {{101.0, 100.0}, {300.0, 301.0}, {201.0, 200.0}, {400.0, 400.0}}, 4.0, 640, 480);
  ASSERT_EQ(depths.size(), 4u);
  EXPECT_DOUBLE_EQ(depths[0], 2.02);  // mean of the two within 5 % of the nearest
  EXPECT_TRUE(std::isnan(depths[1]));  // one sample is not a surface
  EXPECT_TRUE(std::isnan(depths[2]));  // 6 m is not within 5 % of 4 m
  EXPECT_TRUE(std::isnan(depths[3]));  // nothing near
}

TEST(SurfaceDepths, TheRadiusIsAPixelDistance) {
  const std::vector<visual::PixelDepth> samples = {{{10.0, 10.0}, 3.0}, {{10.0, 13.9}, 3.0}, {{10.0, 14.1}, 3.0}};
  // From (10, 10): radius 4 reaches the first two, not the third.
  EXPECT_DOUBLE_EQ(surfaceDepths(samples, {{10.0, 10.0}}, 4.0, 640, 480)[0], 3.0);
  EXPECT_TRUE(std::isnan(surfaceDepths(samples, {{10.0, 6.0}}, 4.0, 640, 480)[0]));  // only the first in reach
  EXPECT_TRUE(std::isnan(surfaceDepths(samples, {{10.0, 10.0}}, 0.0, 640, 480)[0]));
}

TEST(SurfaceDepths, NonFiniteSamplesAndPixelsAreIgnored) {
  const double nan = std::nan("");
  const std::vector<visual::PixelDepth> samples = {
      {{10.0, 10.0}, 3.0}, {{11.0, 10.0}, nan}, {{nan, 10.0}, 3.0}, {{10.0, 11.0}, -1.0}};
  const auto depths = surfaceDepths(samples, {{10.0, 10.0}, {nan, nan}}, 4.0, 640, 480);
  EXPECT_TRUE(std::isnan(depths[0]));  // one usable sample only
  EXPECT_TRUE(std::isnan(depths[1]));
}

}  // namespace
}  // namespace lvslam::fusion
