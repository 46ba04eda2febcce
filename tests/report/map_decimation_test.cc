#include "lvslam/report/map_decimation.h"

#include <gtest/gtest.h>

namespace lvslam::report {
namespace {

std::vector<PlyPoint> grid(int n, float step) {
  std::vector<PlyPoint> points;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      PlyPoint q;
      q.p = Eigen::Vector3f(step * i, step * j, 0.0f);
      q.intensity = static_cast<float>((i + j) % 6);
      points.push_back(q);
    }
  return points;
}

TEST(MapDecimation, UnderTheBudgetEveryPointStays) {
  const DecimatedMap map = decimateMap(grid(10, 0.01f), 100);
  EXPECT_EQ(map.points.size(), 100u);
  EXPECT_EQ(map.voxel_m, 0.0);
}

TEST(MapDecimation, OverTheBudgetOnePointPerVoxelAndTheExtentStays) {
  const std::vector<PlyPoint> points = grid(300, 0.01f);  // 3 m square, 90000 points
  const DecimatedMap map = decimateMap(points, 2000);
  EXPECT_LE(map.points.size(), 2000u);
  EXPECT_GT(map.points.size(), 500u) << "not thinned more than needed";
  EXPECT_GT(map.voxel_m, 0.05);
  float max_x = 0.0f, max_y = 0.0f;
  for (const PlyPoint& q : map.points) {
    max_x = std::max(max_x, q.p.x());
    max_y = std::max(max_y, q.p.y());
  }
  EXPECT_GT(max_x, 3.0f - 2.0f * map.voxel_m);
  EXPECT_GT(max_y, 3.0f - 2.0f * map.voxel_m);
}

TEST(MapDecimation, NegativeCoordinatesFallInTheirOwnVoxels) {
  std::vector<PlyPoint> points(4);
  points[0].p = Eigen::Vector3f(-0.01f, 0, 0);
  points[1].p = Eigen::Vector3f(0.01f, 0, 0);
  points[2].p = Eigen::Vector3f(-0.02f, 0, 0);
  points[3].p = Eigen::Vector3f(0.02f, 0, 0);
  EXPECT_EQ(decimateMap(points, 3).points.size(), 2u);
}

}  // namespace
}  // namespace lvslam::report
