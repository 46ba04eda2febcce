#include "lvslam/system/odometry_path_length.h"

#include <gtest/gtest.h>

namespace lvslam::system {
namespace {

// A 3-4-5 path: 5 m, then 5 m more, then standing still.
TEST(OdometryPathLength, AddsTheDistancesAndLooksUpTheLastTimeNotAfter) {
  OdometryPathLength path;
  EXPECT_FALSE(path.at(0.0).has_value());
  EXPECT_DOUBLE_EQ(path.since(0.0), 0.0);
  path.add(1.0, Eigen::Vector3d(0, 0, 0));
  path.add(2.0, Eigen::Vector3d(3, 4, 0));
  path.add(3.0, Eigen::Vector3d(6, 8, 0));
  path.add(4.0, Eigen::Vector3d(6, 8, 0));
  path.add(3.5, Eigen::Vector3d(100, 0, 0));  // not after the last time: ignored
  EXPECT_FALSE(path.at(0.5).has_value());
  EXPECT_DOUBLE_EQ(*path.at(1.0), 0.0);
  EXPECT_DOUBLE_EQ(*path.at(2.5), 5.0);
  EXPECT_DOUBLE_EQ(*path.at(3.0), 10.0);
  EXPECT_DOUBLE_EQ(*path.at(9.0), 10.0);
  EXPECT_DOUBLE_EQ(path.since(2.0), 5.0);
  EXPECT_DOUBLE_EQ(path.since(4.0), 0.0);
  EXPECT_DOUBLE_EQ(path.since(0.0), 10.0);  // before the first pose: the whole path
}

}  // namespace
}  // namespace lvslam::system
