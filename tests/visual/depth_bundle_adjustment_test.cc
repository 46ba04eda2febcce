// LiDAR keypoint depths in bundle adjustment: a monocular window started at
// a wrong scale keeps it without depths (scale is a gauge freedom) and is
// pulled to the exact true scale by depth observations of one keyframe, also
// when some of those depths are gross outliers.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "lvslam/core/error.h"
#include "lvslam/visual/optimize/bundle_adjustment.h"
#include "visual/bundle_adjustment_errors.h"
#include "visual/synthetic_scene.h"

namespace lvslam::visual {
namespace {

using testing::baErrors;
using testing::SyntheticScene;

constexpr int kDepthKeyframe = 5;

struct ScaleCase {
  SyntheticScene scene;
  BundleAdjustmentProblem problem;
  std::vector<double> true_depth;  // per point observation
};

// Exact observations; the estimate is the truth scaled by `scale` about the
// first camera, which alone is fixed: every reprojection is still exact.
ScaleCase makeScaledWindow(double scale, unsigned seed) {
  ScaleCase c{testing::makeScene(8, 150, 0, 0.15, seed), {}, {}};
  const SyntheticScene& s = c.scene;
  BundleAdjustmentProblem& p = c.problem;
  p.intrinsics = s.K;
  const Eigen::Vector3d c0 = s.T_camera_world[0].inverse().translation();
  for (size_t k = 0; k < s.T_camera_world.size(); ++k) {
    Eigen::Isometry3d T_w_c = s.T_camera_world[k].inverse();
    T_w_c.translation() = c0 + scale * (T_w_c.translation() - c0);
    p.keyframes.push_back({T_w_c.inverse(), k == 0, std::nullopt});
  }
  for (const Eigen::Vector3d& pt : s.points) p.points.push_back({c0 + scale * (pt - c0), false});
  for (size_t k = 0; k < s.T_camera_world.size(); ++k) {
    for (size_t i = 0; i < s.points.size(); ++i) {
      const Eigen::Vector3d uvz = s.project(s.T_camera_world[k], s.points[i]);
      if (!s.visible(uvz)) continue;
      p.point_observations.push_back({static_cast<int>(k), static_cast<int>(i), uvz.head<2>(), 1.0});
      c.true_depth.push_back(uvz.z());
    }
  }
  return c;
}

TEST(DepthBundleAdjustment, WithoutDepthsAWrongScaleStays) {
  ScaleCase c = makeScaledWindow(0.9, 11);
  const double before = baErrors(c.problem, c.scene).max_translation;
  ASSERT_GT(before, 0.05);
  ASSERT_TRUE(runBundleAdjustment(c.problem).usable);
  EXPECT_GT(baErrors(c.problem, c.scene).max_translation, 0.9 * before);
}

TEST(DepthBundleAdjustment, DepthsOfOneKeyframePullTheWindowToTheTrueScale) {
  ScaleCase c = makeScaledWindow(0.9, 11);
  int with_depth = 0;
  for (size_t i = 0; i < c.problem.point_observations.size(); ++i) {
    auto& o = c.problem.point_observations[i];
    if (o.keyframe != kDepthKeyframe) continue;
    o.depth = c.true_depth[i];
    ++with_depth;
  }
  ASSERT_GT(with_depth, 30);
  const BundleAdjustmentResult r = runBundleAdjustment(c.problem);
  ASSERT_TRUE(r.usable);
  EXPECT_LT(baErrors(c.problem, c.scene).max_translation, 1e-6);
  EXPECT_LT(baErrors(c.problem, c.scene).max_point, 1e-6);
  for (size_t i = 0; i < r.depth_inlier.size(); ++i)
    EXPECT_EQ(r.depth_inlier[i], c.problem.point_observations[i].keyframe == kDepthKeyframe) << i;
}

TEST(DepthBundleAdjustment, GrossDepthOutliersLoseOnlyTheirDepthTerm) {
  ScaleCase c = makeScaledWindow(1.1, 12);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<size_t> outliers;
  for (size_t i = 0; i < c.problem.point_observations.size(); ++i) {
    auto& o = c.problem.point_observations[i];
    if (o.keyframe != kDepthKeyframe && o.keyframe != 2) continue;
    o.depth = c.true_depth[i];
    if (unit(rng) < 0.15) {  // another surface under the keypoint: 40 % off
      o.depth *= unit(rng) < 0.5 ? 0.6 : 1.4;
      outliers.push_back(i);
    }
  }
  ASSERT_GT(outliers.size(), 5u);
  const BundleAdjustmentResult r = runBundleAdjustment(c.problem);
  ASSERT_TRUE(r.usable);
  for (const size_t i : outliers) {
    EXPECT_FALSE(r.depth_inlier[i]) << i;
    EXPECT_TRUE(r.point_inlier[i]) << i;
  }
  EXPECT_LT(baErrors(c.problem, c.scene).max_translation, 1e-5);
  EXPECT_LT(baErrors(c.problem, c.scene).max_point, 1e-5);
}

TEST(DepthBundleAdjustment, RejectsNonPositiveDepthsAndIgnoresNaN) {
  ScaleCase c = makeScaledWindow(1.0, 13);
  c.problem.point_observations[0].depth = std::numeric_limits<double>::quiet_NaN();
  const BundleAdjustmentResult r = runBundleAdjustment(c.problem);
  EXPECT_FALSE(r.depth_inlier[0]);
  EXPECT_TRUE(r.point_inlier[0]);
  c.problem.point_observations[0].depth = 0.0;
  EXPECT_THROW(runBundleAdjustment(c.problem), Error);
  c.problem.point_observations[0].depth = -2.0;
  EXPECT_THROW(runBundleAdjustment(c.problem), Error);
  c.problem.point_observations[0].depth = 3.0;
  BundleAdjustmentConfig config;
  config.depth_sigma_ratio = 0.0;
  EXPECT_THROW(runBundleAdjustment(c.problem, config), Error);
}

}  // namespace
}  // namespace lvslam::visual
