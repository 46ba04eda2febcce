#include "lvslam/visual/initialize/two_view_initializer.h"

#include <random>

#include <gtest/gtest.h>

#include "lvslam/core/error.h"
#include "lvslam/core/se3.h"
#include "lvslam/visual/initialize/two_view_geometry.h"

namespace lvslam::visual {
namespace {

const PinholeIntrinsics kK{450.0, 450.0, 320.0, 240.0};

struct TwoViews {
  std::vector<Eigen::Vector3d> points_c1;
  std::vector<Eigen::Vector2d> x1, x2;
  std::vector<TwoViewMatch> matches;
};

Eigen::Vector2d project(const Eigen::Vector3d& p) { return {kK.fx * p.x() / p.z() + kK.cx, kK.fy * p.y() / p.z() + kK.cy}; }

// planar: points on the floor 1.2 m below the camera (y down), 2.5..10 m
// ahead (else a volume 4..9 m deep).
TwoViews makeViews(const Eigen::Isometry3d& T_c2_c1, bool planar, double noise_px, unsigned seed) {
  TwoViews v;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0), depth(4.0, 9.0);
  std::normal_distribution<double> n(0.0, noise_px);
  while (v.points_c1.size() < 300) {
    const double z = planar ? 2.5 + 3.75 * (u(rng) + 1.0) : depth(rng);
    Eigen::Vector3d p(u(rng) * 0.6 * z, u(rng) * 0.45 * z, z);
    if (planar) p.y() = 1.2;
    const Eigen::Vector3d p2 = T_c2_c1 * p;
    if (p2.z() < 0.5) continue;
    const Eigen::Vector2d a = project(p), b = project(p2);
    if (b.x() < 0 || b.x() > 640 || b.y() < 0 || b.y() > 480) continue;
    v.points_c1.push_back(p);
    // Keypoint lists in a different order in each view, as after matching.
    v.x1.push_back(a + Eigen::Vector2d(n(rng), n(rng)));
    v.x2.insert(v.x2.begin(), b + Eigen::Vector2d(n(rng), n(rng)));
  }
  const int N = static_cast<int>(v.points_c1.size());
  for (int i = 0; i < N; ++i) v.matches.push_back({i, N - 1 - i});
  return v;
}

Eigen::Isometry3d motion() {
  Vector6d xi;
  xi << 0.4, 0.05, 0.1, 0.02, -0.06, 0.01;
  return expSE3(xi);
}

double angleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 / M_PI;
}

TEST(TwoViewGeometry, DltTriangulatesExactly) {
  Eigen::Matrix3d K;
  K << kK.fx, 0, kK.cx, 0, kK.fy, kK.cy, 0, 0, 1;
  const Eigen::Isometry3d T = motion();
  Eigen::Matrix<double, 3, 4> P1, P2;
  P1 << K, Eigen::Vector3d::Zero();
  P2 << K * T.linear(), K * T.translation();
  const Eigen::Vector3d X(0.7, -0.4, 6.0);
  EXPECT_LT((triangulateDlt(P1, P2, project(X), project(T * X)) - X).norm(), 1e-9);
}

TEST(TwoViewInitializer, GeneralSceneChoosesTheEssentialMatrixAndRecoversMotion) {
  const Eigen::Isometry3d T = motion();
  const TwoViews v = makeViews(T, false, 0.0, 1);
  const TwoViewInitializer init(TwoViewInitializerConfig{}, kK);
  const auto r = init.initialize(v.x1, v.x2, v.matches);
  ASSERT_TRUE(r.has_value());
  EXPECT_FALSE(r->used_homography);
  EXPECT_FALSE(r->metric);
  EXPECT_LT(rotationAngle(r->T_c2_c1 * Eigen::Isometry3d(T.linear().transpose())), 1e-6);
  EXPECT_LT(angleDeg(r->T_c2_c1.translation(), T.translation()), 1e-4);
  EXPECT_GT(r->num_triangulated, 250);
  // Up to scale, the structure is the truth; the median depth is 1.
  const double s = T.translation().norm() / r->T_c2_c1.translation().norm();
  std::vector<double> z;
  for (size_t i = 0; i < v.points_c1.size(); ++i) {
    if (!r->triangulated[i]) continue;
    EXPECT_LT((s * r->points_c1[i] - v.points_c1[i]).norm(), 1e-5 * v.points_c1[i].norm());
    z.push_back(r->points_c1[i].z());
  }
  std::nth_element(z.begin(), z.begin() + z.size() / 2, z.end());
  EXPECT_NEAR(z[z.size() / 2], 1.0, 1e-9);
}

TEST(TwoViewInitializer, DepthHintsMakeTheMapMetric) {
  const Eigen::Isometry3d T = motion();
  const TwoViews v = makeViews(T, false, 0.0, 2);
  TwoViewInitializer init(TwoViewInitializerConfig{}, kK);
  std::vector<DepthHint> hints;
  for (int i = 0; i < 40; i += 3) hints.push_back({i, v.points_c1[i].z()});
  init.setDepthHints(hints);
  const auto r = init.initialize(v.x1, v.x2, v.matches);
  ASSERT_TRUE(r.has_value());
  EXPECT_TRUE(r->metric);
  EXPECT_LT((r->T_c2_c1.translation() - T.translation()).norm(), 1e-6);
  for (size_t i = 0; i < v.points_c1.size(); ++i) {
    if (r->triangulated[i]) {
      EXPECT_LT((r->points_c1[i] - v.points_c1[i]).norm(), 1e-5);
    }
  }
  // Too few hints: back to median depth 1.
  init.setDepthHints({hints.begin(), hints.begin() + 3});
  EXPECT_FALSE(init.initialize(v.x1, v.x2, v.matches)->metric);
}

TEST(TwoViewInitializer, PlanarSceneIsAmbiguousWithoutHintsAndResolvedWithThem) {
  const Eigen::Isometry3d T = motion();
  const TwoViews v = makeViews(T, true, 0.3, 3);
  TwoViewInitializer init(TwoViewInitializerConfig{}, kK);
  // Two views of a plane admit two motions (the homography's two-fold
  // ambiguity); with nothing to choose between them the initializer waits.
  EXPECT_FALSE(init.initialize(v.x1, v.x2, v.matches).has_value());
  std::vector<DepthHint> hints;
  for (int i = 0; i < 30; ++i) hints.push_back({i, v.points_c1[i].z()});
  init.setDepthHints(hints);
  const auto r = init.initialize(v.x1, v.x2, v.matches);
  ASSERT_TRUE(r.has_value());
  EXPECT_TRUE(r->used_homography);
  EXPECT_LT(rotationAngle(r->T_c2_c1 * Eigen::Isometry3d(T.linear().transpose())), 0.3 * M_PI / 180.0);
  EXPECT_LT((r->T_c2_c1.translation() - T.translation()).norm(), 0.03);
}

TEST(TwoViewInitializer, NoisyGeneralSceneStaysAccurate) {
  const Eigen::Isometry3d T = motion();
  const TwoViews v = makeViews(T, false, 0.5, 4);
  const auto r = TwoViewInitializer(TwoViewInitializerConfig{}, kK).initialize(v.x1, v.x2, v.matches);
  ASSERT_TRUE(r.has_value());
  EXPECT_FALSE(r->used_homography);
  EXPECT_LT(rotationAngle(r->T_c2_c1 * Eigen::Isometry3d(T.linear().transpose())), 0.2 * M_PI / 180.0);
  EXPECT_LT(angleDeg(r->T_c2_c1.translation(), T.translation()), 3.0);
}

TEST(TwoViewInitializer, RefusesPureRotationAndBadInput) {
  Eigen::Isometry3d rotation_only = Eigen::Isometry3d::Identity();
  rotation_only.linear() = expSO3(Eigen::Vector3d(0.02, 0.08, 0.0));
  const TwoViews v = makeViews(rotation_only, false, 0.3, 5);
  const TwoViewInitializer init(TwoViewInitializerConfig{}, kK);
  EXPECT_FALSE(init.initialize(v.x1, v.x2, v.matches).has_value());
  // Too few matches.
  EXPECT_FALSE(init.initialize(v.x1, v.x2, {v.matches.begin(), v.matches.begin() + 20}).has_value());
  // Out-of-range index.
  EXPECT_THROW(init.initialize(v.x1, v.x2, {{0, 100000}}), Error);
  // Non-finite pixels.
  TwoViews bad = makeViews(motion(), false, 0.0, 6);
  bad.x1[3].x() = NAN;
  EXPECT_FALSE(init.initialize(bad.x1, bad.x2, bad.matches).has_value());
}

}  // namespace
}  // namespace lvslam::visual
