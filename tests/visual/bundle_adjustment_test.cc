#include "lvslam/visual/optimize/bundle_adjustment.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "lvslam/core/error.h"
#include "lvslam/visual/geometry/orthonormal_line.h"
#include "visual/bundle_adjustment_errors.h"
#include "visual/synthetic_scene.h"

namespace lvslam::visual {
namespace {

using testing::SyntheticScene;
using testing::BaErrors;
using testing::baErrors;

struct Truth {
  SyntheticScene scene;
  BundleAdjustmentProblem problem;  // exact observations, true values
  std::vector<int> gross_point_outliers;
};

Truth makeProblem(double pixel_noise, double outlier_fraction, unsigned seed) {
  Truth t{testing::makeScene(8, 150, 30, 0.15, seed), {}, {}};
  const SyntheticScene& s = t.scene;
  BundleAdjustmentProblem& p = t.problem;
  p.intrinsics = s.K;
  std::mt19937 rng(seed + 1);
  std::normal_distribution<double> noise(0.0, pixel_noise);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (size_t k = 0; k < s.T_camera_world.size(); ++k) p.keyframes.push_back({s.T_camera_world[k], k < 2, std::nullopt});
  for (const auto& pt : s.points) p.points.push_back({pt, false});
  for (const auto& seg : s.segments) p.lines.push_back({testing::lineOf(seg), std::nullopt, false});
  for (size_t k = 0; k < s.T_camera_world.size(); ++k) {
    for (size_t i = 0; i < s.points.size(); ++i) {
      const Eigen::Vector3d uvz = s.project(s.T_camera_world[k], s.points[i]);
      if (!s.visible(uvz)) continue;
      Eigen::Vector2d px = uvz.head<2>() + Eigen::Vector2d(noise(rng), noise(rng));
      if (unit(rng) < outlier_fraction) {
        px += Eigen::Vector2d(25.0, -20.0);
        t.gross_point_outliers.push_back(static_cast<int>(p.point_observations.size()));
      }
      p.point_observations.push_back({static_cast<int>(k), static_cast<int>(i), px, 1.0});
    }
    for (size_t j = 0; j < s.segments.size(); ++j) {
      // Each view sees a different part of the segment.
      const auto& seg = s.segments[j];
      const double f0 = 0.2 * unit(rng), f1 = 1.0 - 0.2 * unit(rng);
      const Eigen::Vector3d a = s.project(s.T_camera_world[k], seg.a + f0 * (seg.b - seg.a));
      const Eigen::Vector3d b = s.project(s.T_camera_world[k], seg.a + f1 * (seg.b - seg.a));
      if (!s.visible(a) || !s.visible(b)) continue;
      p.line_observations.push_back({static_cast<int>(k), static_cast<int>(j),
                                     a.head<2>() + Eigen::Vector2d(noise(rng), noise(rng)),
                                     b.head<2>() + Eigen::Vector2d(noise(rng), noise(rng)), 1.0});
    }
  }
  return t;
}

void perturb(BundleAdjustmentProblem& p, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  for (auto& k : p.keyframes) {
    if (k.fixed) continue;
    Vector6d xi;
    xi << 0.03 * n(rng), 0.03 * n(rng), 0.03 * n(rng), 0.01 * n(rng), 0.01 * n(rng), 0.01 * n(rng);
    k.T_camera_world = expSE3(xi) * k.T_camera_world;
  }
  for (auto& pt : p.points) pt.p_world += 0.05 * Eigen::Vector3d(n(rng), n(rng), n(rng));
  for (auto& l : p.lines) {
    const Eigen::Vector4d delta(0.01 * n(rng), 0.01 * n(rng), 0.01 * n(rng), 0.01 * n(rng));
    l.line_world = OrthonormalLine::fromPlucker(l.line_world).plus(delta).toPlucker();
  }
}

TEST(BundleAdjustment, ConvergesToTheTruthFromPerturbedStartWithExactObservations) {
  Truth t = makeProblem(0.0, 0.0, 3);
  ASSERT_GT(t.problem.line_observations.size(), 100u);
  perturb(t.problem, 4);
  const BaErrors before = baErrors(t.problem, t.scene);
  EXPECT_GT(before.max_translation, 0.02);
  const BundleAdjustmentResult r = runBundleAdjustment(t.problem);
  ASSERT_TRUE(r.usable);
  EXPECT_LT(r.final_cost, 1e-8 * r.initial_cost);
  const BaErrors after = baErrors(t.problem, t.scene);
  EXPECT_LT(after.max_translation, 1e-6);
  EXPECT_LT(after.max_rotation, 1e-7);
  EXPECT_LT(after.max_point, 1e-5);
  EXPECT_LT(after.max_line, 1e-6);
  for (bool in : r.point_inlier) EXPECT_TRUE(in);
  for (bool in : r.line_inlier) EXPECT_TRUE(in);
  // Fixed keyframes did not move.
  EXPECT_TRUE(t.problem.keyframes[0].T_camera_world.isApprox(t.scene.T_camera_world[0], 1e-12));
}

TEST(BundleAdjustment, RejectsGrossOutliersAndStaysAccurateUnderNoise) {
  Truth t = makeProblem(0.5, 0.05, 7);
  ASSERT_GT(t.gross_point_outliers.size(), 10u);
  perturb(t.problem, 8);
  const BundleAdjustmentResult r = runBundleAdjustment(t.problem);
  ASSERT_TRUE(r.usable);
  for (const int i : t.gross_point_outliers) EXPECT_FALSE(r.point_inlier[i]) << "observation " << i;
  const size_t inliers = std::count(r.point_inlier.begin(), r.point_inlier.end(), true);
  const size_t clean = r.point_inlier.size() - t.gross_point_outliers.size();
  EXPECT_GT(inliers, 0.93 * clean);  // chi2 at 95 % drops about 5 % of clean ones
  const BaErrors after = baErrors(t.problem, t.scene);
  EXPECT_LT(after.max_translation, 0.01);
  EXPECT_LT(after.max_rotation, 0.002);
}

TEST(BundleAdjustment, FusionDirectionConstrainsAPoorlyTriangulatedLine) {
  // Two fixed cameras 2 cm apart see one line: its depth and direction are
  // weakly determined by the endpoints alone, the fusion direction fixes it.
  const Eigen::Vector3d A(-1.0, -0.5, 5.0), B(1.0, 0.8, 7.0);
  const PluckerLine truth = PluckerLine::fromPoints(A, B);
  auto run = [&](bool with_direction) {
    BundleAdjustmentProblem p;
    p.intrinsics = PinholeIntrinsics{450.0, 450.0, 320.0, 240.0};
    for (int k = 0; k < 2; ++k) {
      Eigen::Isometry3d T_w_c = Eigen::Isometry3d::Identity();
      T_w_c.translation() = Eigen::Vector3d(0.02 * k, 0.0, 0.0);
      p.keyframes.push_back({T_w_c.inverse(), true, std::nullopt});
    }
    p.lines.push_back({OrthonormalLine::fromPlucker(truth).plus(Eigen::Vector4d(0.05, -0.08, 0.06, 0.1)).toPlucker(),
                       truth.d, false});
    std::mt19937 rng(2);
    std::normal_distribution<double> noise(0.0, 0.5);
    for (int k = 0; k < 2; ++k) {
      const Eigen::Isometry3d& T = p.keyframes[k].T_camera_world;
      auto px = [&](const Eigen::Vector3d& X) {
        const Eigen::Vector3d c = T * X;
        return Eigen::Vector2d(450.0 * c.x() / c.z() + 320.0 + noise(rng), 450.0 * c.y() / c.z() + 240.0 + noise(rng));
      };
      p.line_observations.push_back({k, 0, px(A), px(B), 1.0});
    }
    BundleAdjustmentConfig config;
    config.use_direction_residual = with_direction;
    runBundleAdjustment(p, config);
    return testing::angleBetweenLines(p.lines[0].line_world, truth);
  };
  const double without = run(false), with = run(true);
  EXPECT_GT(without, 0.01);
  EXPECT_LT(with, 0.02 * without);
  EXPECT_LT(with, 1.0 * M_PI / 180.0);
}

// With no keyframe fixed, the LiDAR pose priors alone hold the gauge: exact
// priors and observations bring every keyframe and point back to the truth
// in absolute terms, which images alone cannot (any rigid motion of the
// whole scene fits them equally).
TEST(BundleAdjustment, PosePriorsHoldTheGaugeWithoutFixedKeyframes) {
  Truth t = makeProblem(0.0, 0.0, 21);
  for (size_t k = 0; k < t.problem.keyframes.size(); ++k) {
    t.problem.keyframes[k].fixed = false;
    t.problem.keyframes[k].prior_T_camera_world = t.scene.T_camera_world[k];
  }
  perturb(t.problem, 22);
  EXPECT_GT(baErrors(t.problem, t.scene).max_translation, 0.02);
  const BundleAdjustmentResult r = runBundleAdjustment(t.problem);
  ASSERT_TRUE(r.usable);
  const BaErrors after = baErrors(t.problem, t.scene);
  EXPECT_LT(after.max_translation, 1e-5);
  EXPECT_LT(after.max_rotation, 1e-6);
  EXPECT_LT(after.max_point, 1e-4);
  // A prior that is not a rigid transform is refused.
  t.problem.keyframes[1].prior_T_camera_world->matrix()(0, 0) = std::nan("");
  EXPECT_THROW(runBundleAdjustment(t.problem), Error);
}

TEST(BundleAdjustment, RejectsBadIndicesAndHandlesEmptyProblems) {
  BundleAdjustmentProblem p;
  p.keyframes.push_back({});
  p.points.push_back({Eigen::Vector3d(0, 0, 5), false});
  p.point_observations.push_back({1, 0, Eigen::Vector2d::Zero(), 1.0});
  EXPECT_THROW(runBundleAdjustment(p), Error);
  p.point_observations[0] = {0, 3, Eigen::Vector2d::Zero(), 1.0};
  EXPECT_THROW(runBundleAdjustment(p), Error);
  p.point_observations[0] = {0, 0, Eigen::Vector2d::Zero(), -1.0};
  EXPECT_THROW(runBundleAdjustment(p), Error);
  p.point_observations.clear();
  EXPECT_FALSE(runBundleAdjustment(p).usable);
  // A point behind the only camera is an outlier, not a crash.
  p.points[0].p_world = Eigen::Vector3d(0, 0, -5);
  p.point_observations.push_back({0, 0, Eigen::Vector2d(1, 1), 1.0});
  const BundleAdjustmentResult r = runBundleAdjustment(p);
  EXPECT_FALSE(r.point_inlier[0]);
}

}  // namespace
}  // namespace lvslam::visual
