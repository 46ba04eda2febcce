#include "lvslam/system/lidar_map_export.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "lvslam/core/se3.h"

namespace lvslam::system {
namespace {

using lidar::FeatureClass;
using lidar::FeatureFrame;
using lidar::FeaturePoint;

FeaturePoint point(float x, float y, float z, FeatureClass cls) {
  FeaturePoint p;
  p.p = Eigen::Vector3f(x, y, z);
  p.cls = cls;
  return p;
}

// A quarter turn about z and a translation, all exactly representable in float.
Eigen::Isometry3d quarterTurn() {
  Eigen::Matrix3d R;
  R << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  return makePose(R, Eigen::Vector3d(1.0, 2.0, 3.0));
}

TEST(LidarMapExport, AppliesTheFramePoseAndKeepsTheClassAsIntensity) {
  LidarMapExport map(0.5);
  FeatureFrame frame;
  frame.T_world_lidar = quarterTurn();
  frame.points = {point(1.0f, 0.0f, 0.0f, FeatureClass::kPillar), point(0.0f, 2.0f, -1.0f, FeatureClass::kGround),
                  point(0.25f, 0.5f, 4.0f, FeatureClass::kVertex)};
  map.add(frame);
  ASSERT_EQ(map.points().size(), 3u);
  // p_world = R p + t with R (x, y, z) -> (-y, x, z).
  EXPECT_EQ(map.points()[0].p, Eigen::Vector3f(1.0f, 3.0f, 3.0f));
  EXPECT_EQ(map.points()[1].p, Eigen::Vector3f(-1.0f, 2.0f, 2.0f));
  EXPECT_EQ(map.points()[2].p, Eigen::Vector3f(0.5f, 2.25f, 7.0f));
  EXPECT_EQ(map.points()[0].intensity, static_cast<float>(FeatureClass::kPillar));
  EXPECT_EQ(map.points()[1].intensity, 0.0f);  // ground
  EXPECT_EQ(map.points()[2].intensity, 5.0f);  // vertex
}

TEST(LidarMapExport, GeneralPoseMatchesTheTransformedPoint) {
  LidarMapExport map(0.01);
  FeatureFrame frame;
  frame.T_world_lidar = makePose(expSO3(Eigen::Vector3d(0.3, -0.7, 1.1)), Eigen::Vector3d(-4.5, 0.25, 1.75));
  for (int i = 0; i < 20; ++i)
    frame.points.push_back(point(0.37f * i, -0.21f * i + 1.0f, 0.05f * i * i, FeatureClass::kFacade));
  map.add(frame);
  ASSERT_EQ(map.points().size(), frame.points.size());  // 1 cm voxels: all apart
  for (std::size_t i = 0; i < frame.points.size(); ++i) {
    const Eigen::Vector3d expected = frame.T_world_lidar * frame.points[i].p.cast<double>();
    EXPECT_LT((map.points()[i].p.cast<double>() - expected).norm(), 1e-5) << i;
  }
}

TEST(LidarMapExport, OnePointPerVoxelTheFirstSeenAcrossFrames) {
  LidarMapExport map(0.5);
  FeatureFrame first;  // identity pose
  first.points = {point(0.1f, 0.1f, 0.1f, FeatureClass::kFacade),
                  point(0.4f, 0.3f, 0.2f, FeatureClass::kPillar),    // same voxel [0, 0.5)^3: dropped
                  point(-0.1f, 0.1f, 0.1f, FeatureClass::kFacade),   // x voxel -1: kept
                  point(0.6f, 0.1f, 0.1f, FeatureClass::kBeam)};     // x voxel 1: kept
  map.add(first);
  ASSERT_EQ(map.points().size(), 3u);
  EXPECT_EQ(map.points()[0].p, Eigen::Vector3f(0.1f, 0.1f, 0.1f));
  EXPECT_EQ(map.points()[0].intensity, static_cast<float>(FeatureClass::kFacade));
  EXPECT_EQ(map.points()[1].p, Eigen::Vector3f(-0.1f, 0.1f, 0.1f));
  EXPECT_EQ(map.points()[2].p, Eigen::Vector3f(0.6f, 0.1f, 0.1f));

  // A later frame moved by 0.25 m in x: its (0.0, 0.1, 0.1) lands at x = 0.25,
  // in the first voxel (taken); (1.0, 0.1, 0.1) lands at 1.25, a new voxel.
  FeatureFrame second;
  second.T_world_lidar = makePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.25, 0.0, 0.0));
  second.points = {point(0.0f, 0.1f, 0.1f, FeatureClass::kRoof), point(1.0f, 0.1f, 0.1f, FeatureClass::kRoof)};
  map.add(second);
  ASSERT_EQ(map.points().size(), 4u);
  EXPECT_EQ(map.points()[0].intensity, static_cast<float>(FeatureClass::kFacade));  // the first seen stays
  EXPECT_EQ(map.points()[3].p, Eigen::Vector3f(1.25f, 0.1f, 0.1f));
  EXPECT_EQ(map.points()[3].intensity, static_cast<float>(FeatureClass::kRoof));
}

TEST(LidarMapExport, NonFinitePointsAreSkipped) {
  LidarMapExport map(0.5);
  FeatureFrame frame;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  frame.points = {point(nan, 0.0f, 0.0f, FeatureClass::kFacade), point(1.0f, inf, 0.0f, FeatureClass::kFacade),
                  point(2.0f, 2.0f, 2.0f, FeatureClass::kPillar)};
  map.add(frame);
  ASSERT_EQ(map.points().size(), 1u);
  EXPECT_EQ(map.points()[0].p, Eigen::Vector3f(2.0f, 2.0f, 2.0f));
  for (const PlyPoint& p : map.points()) EXPECT_TRUE(p.p.allFinite());
}

TEST(LidarMapExport, EmptyFrameAddsNothing) {
  LidarMapExport map(0.2);
  map.add(FeatureFrame{});
  EXPECT_TRUE(map.points().empty());
}

}  // namespace
}  // namespace lvslam::system
