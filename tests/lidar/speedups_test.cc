// The shortcuts that keep the odometry within its time budget give the same
// answers as the plain computations they replace.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "lvslam/lidar/local_map.h"
#include "lvslam/lidar/point_kdtree.h"
#include "lvslam/lidar/preprocess.h"

namespace lvslam::lidar {
namespace {

TEST(KnnWithinRadius, EqualsBruteForceKNearestInsideTheRadius) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> coordinate(-5.0f, 5.0f);
  std::vector<TimedPoint> cloud(3000);
  for (TimedPoint& point : cloud) point.p = Eigen::Vector3f(coordinate(rng), coordinate(rng), coordinate(rng));
  const PointCloudAdaptor<TimedPoint> adaptor{cloud};
  PointKdTree<TimedPoint> tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  for (const float radius : {0.3f, 0.8f, 3.0f}) {
    for (std::size_t q = 0; q < cloud.size(); q += 97) {
      std::array<std::size_t, 20> ids{};
      std::array<float, 20> dist_sq{};
      const std::size_t found = knnWithinRadius(tree, cloud[q].p.data(), ids.size(), radius, ids.data(), dist_sq.data());
      std::vector<std::pair<float, std::size_t>> expected;
      for (std::size_t i = 0; i < cloud.size(); ++i) {
        const float d = (cloud[i].p - cloud[q].p).squaredNorm();
        if (d < radius * radius) expected.emplace_back(d, i);
      }
      std::sort(expected.begin(), expected.end());
      expected.resize(std::min(expected.size(), ids.size()));
      ASSERT_EQ(found, expected.size()) << "radius " << radius << " query " << q;
      for (std::size_t j = 0; j < found; ++j) {
        EXPECT_EQ(ids[j], expected[j].second);
        EXPECT_FLOAT_EQ(dist_sq[j], expected[j].first);
      }
    }
  }
}

TEST(RangeAdaptiveDownsample, GrowsTheVoxelWithRangeOnlyWhereTheAngleSpansMore) {
  PreprocessConfig config;
  config.voxel_size = 0.25;
  config.voxel_angle_deg = 1.0;
  const double tan1 = std::tan(M_PI / 180.0);
  EXPECT_DOUBLE_EQ(voxelSizeAt(3.0, config), 0.25);           // 5 m * tan(1 deg) = 0.087 m
  EXPECT_DOUBLE_EQ(voxelSizeAt(52.0, config), 55.0 * tan1);   // band 50-55 m
  EXPECT_DOUBLE_EQ(voxelSizeAt(15.0, config), 0.25 > 20.0 * tan1 ? 0.25 : 20.0 * tan1);

  // Near points: exactly what the fixed voxel keeps.
  std::vector<TimedPoint> near;
  for (int i = 0; i < 400; ++i) near.push_back({Eigen::Vector3f(2.0f + 0.01f * i, 0.013f * i, 0.3f), 0.0f, 0});
  const auto fixed = voxelDownsample(near, config.voxel_size, [](const TimedPoint& tp) { return tp.p; });
  const auto adaptive = rangeAdaptiveDownsample(near, config);
  ASSERT_EQ(adaptive.size(), fixed.size());
  for (std::size_t i = 0; i < fixed.size(); ++i) EXPECT_EQ(adaptive[i].p, fixed[i].p);

  // A dense ring arc 52 m away (5 cm steps over 20 m): about one point per
  // 0.96 m voxel instead of one per 0.25 m.
  std::vector<TimedPoint> far;
  for (int i = 0; i < 400; ++i) {
    const double angle = 0.05 * i / 52.0;
    far.push_back({Eigen::Vector3f(52.0 * std::cos(angle), 52.0 * std::sin(angle), 0.1f), 0.0f, 0});
  }
  const std::size_t kept = rangeAdaptiveDownsample(far, config).size();
  const double arc_per_voxel = 20.0 / (55.0 * tan1);
  EXPECT_GE(static_cast<double>(kept), arc_per_voxel - 1.0);
  EXPECT_LE(static_cast<double>(kept), 2.0 * arc_per_voxel + 2.0);  // a diagonal arc crosses x and y voxels
  EXPECT_LT(kept, voxelDownsample(far, config.voxel_size, [](const TimedPoint& tp) { return tp.p; }).size() / 2);

  // Corrupt input: non-finite and absurdly far points are dropped; 800 m
  // shares the last range band.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<TimedPoint> corrupt{{Eigen::Vector3f(nan, 0, 0), 0.0f, 0},
                                        {Eigen::Vector3f(1e30f, 0, 0), 0.0f, 0},
                                        {Eigen::Vector3f(2e5f, 0, 0), 0.0f, 0},
                                        {Eigen::Vector3f(800, 0, 0), 0.0f, 0},
                                        {Eigen::Vector3f(3, 0, 0), 0.0f, 0}};
  const auto cleaned = rangeAdaptiveDownsample(corrupt, config);
  ASSERT_EQ(cleaned.size(), 2u);
  EXPECT_EQ(cleaned[0].p.x(), 800.0f);
  EXPECT_EQ(cleaned[1].p.x(), 3.0f);
}

// Frames of random points along a drive; after each update the map holds
// exactly the points that stayed young enough and within the radius.
TEST(LocalMapPrune, KeepsExactlyTheYoungPointsWithinTheRadius) {
  LocalMapConfig config;
  config.radius = 6.0;
  config.max_frame_age = 5;
  config.max_points_per_voxel = 1000;  // no cap: every point is accounted for
  LocalMap map(config);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> offset(-8.0f, 8.0f);
  std::vector<std::pair<std::uint32_t, Eigen::Vector3f>> all;  // (seq, world point)
  Eigen::Vector3f sensor = Eigen::Vector3f::Zero();
  for (std::uint32_t seq = 0; seq < 12; ++seq) {
    FeatureFrame frame;
    frame.seq = seq;
    sensor = Eigen::Vector3f(0.7f * seq, 0.0f, 0.0f);
    frame.T_world_lidar = Eigen::Translation3d(sensor.cast<double>()) * Eigen::Isometry3d::Identity();
    for (int i = 0; i < 300; ++i) {
      FeaturePoint fp;
      fp.p = Eigen::Vector3f(offset(rng), offset(rng), 0.2f * offset(rng));
      frame.points.push_back(fp);
      all.emplace_back(seq, fp.p + sensor);
    }
    map.update(frame);
    // A point once dropped stays dropped: apply the rule to the survivors.
    std::erase_if(all, [&](const auto& entry) {
      return (entry.first + 5 < seq && seq > 5) || (entry.second - sensor).norm() > 6.0f;
    });
    EXPECT_EQ(map.size(), all.size()) << "after frame " << seq;
    EXPECT_EQ(map.points().size(), all.size()) << "after frame " << seq;
  }
  for (const MapPoint& mp : map.points()) {
    EXPECT_LE((mp.p - sensor).norm(), 6.0f + 1e-4f);
    EXPECT_GE(frameOf(mp.id), 11u - 5u);
  }
}

}  // namespace
}  // namespace lvslam::lidar
