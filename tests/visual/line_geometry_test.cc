#include <cmath>
#include <random>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "lvslam/core/se3.h"
#include "lvslam/visual/geometry/line_projection.h"
#include "lvslam/visual/geometry/line_triangulation.h"
#include "lvslam/visual/geometry/orthonormal_line.h"
#include "lvslam/visual/geometry/segment_trimming.h"

namespace lvslam::visual {
namespace {

// Two Plücker vectors describe the same line when they are parallel in R^6.
double sameLineError(const PluckerLine& a, const PluckerLine& b) {
  const Vector6d va = a.vector().normalized(), vb = b.vector().normalized();
  return std::min((va - vb).norm(), (va + vb).norm());
}

Eigen::Matrix3d testK() {
  Eigen::Matrix3d K;
  K << 450.0, 0.0, 320.0, 0.0, 460.0, 240.0, 0.0, 0.0, 1.0;
  return K;
}

TEST(OrthonormalLine, RoundTripKeepsTheLine) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  for (int i = 0; i < 50; ++i) {
    const PluckerLine L = PluckerLine::fromPoints({u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)});
    const OrthonormalLine o = OrthonormalLine::fromPlucker(L);
    EXPECT_TRUE(isRotation(o.U, 1e-12));
    EXPECT_NEAR(o.w.norm(), 1.0, 1e-12);
    const PluckerLine back = o.toPlucker();
    EXPECT_NEAR(back.vector().norm(), 1.0, 1e-12);
    EXPECT_LT(sameLineError(L, back), 1e-12);
    // Same sign, not just the same line: the representation keeps orientation.
    EXPECT_GT(back.d.dot(L.d), 0.0);
  }
  // A line through the origin (m = 0) is representable too.
  const PluckerLine through_origin = PluckerLine::fromPoints({1, 2, 3}, {2, 4, 6});
  EXPECT_LT(sameLineError(through_origin, OrthonormalLine::fromPlucker(through_origin).toPlucker()), 1e-12);
}

TEST(OrthonormalLine, PlusMinusAreInverse) {
  const OrthonormalLine o = OrthonormalLine::fromPlucker(PluckerLine::fromPoints({1, -2, 4}, {3, 1, 5}));
  const Eigen::Vector4d delta(0.1, -0.2, 0.05, 0.3);
  EXPECT_LT((o.minus(o.plus(delta)) - delta).norm(), 1e-12);
  EXPECT_LT(o.minus(o).norm(), 1e-15);
}

TEST(OrthonormalLine, PlusJacobianMatchesNumeric) {
  const OrthonormalLine o = OrthonormalLine::fromPlucker(PluckerLine::fromPoints({1, -2, 4}, {3, 1, 5}));
  const Eigen::Matrix<double, 6, 4> J = orthonormalPlusJacobian(o);
  const double h = 1e-6;
  for (int k = 0; k < 4; ++k) {
    Eigen::Vector4d dp = Eigen::Vector4d::Zero(), dm = Eigen::Vector4d::Zero();
    dp[k] = h;
    dm[k] = -h;
    const Vector6d numeric = (o.plus(dp).toPlucker().vector() - o.plus(dm).toPlucker().vector()) / (2 * h);
    EXPECT_LT((numeric - J.col(k)).norm(), 1e-8) << "column " << k;
  }
}

TEST(LineProjection, ProjectedLinePassesThroughProjectedPoints) {
  const Eigen::Matrix3d K = testK();
  const Eigen::Matrix3d K_line = lineProjectionMatrix(K(0, 0), K(1, 1), K(0, 2), K(1, 2));
  EXPECT_TRUE(K_line.isApprox(K.determinant() * K.inverse().transpose()));
  const Eigen::Vector3d A(-1.0, 0.5, 4.0), B(2.0, -0.3, 6.0);
  const Eigen::Vector3d l = projectLine(K_line, PluckerLine::fromPoints(A, B));
  for (const double s : {0.0, 0.3, 1.0, 1.7}) {
    const Eigen::Vector3d x = K * (A + s * (B - A));
    EXPECT_NEAR(l.dot(x / x.z()) / l.head<2>().norm(), 0.0, 1e-9);
  }
  // Endpoints on the line along the rays through the projected points.
  const Eigen::Vector2d a_px = (K * A).hnormalized(), b_px = (K * B).hnormalized();
  const auto ends = segmentEndpointsOnLine(PluckerLine::fromPoints(A, B), K, a_px, b_px);
  ASSERT_TRUE(ends.has_value());
  EXPECT_LT((ends->start - A).norm(), 1e-9);
  EXPECT_LT((ends->end - B).norm(), 1e-9);
}

struct TwoViews {
  Eigen::Isometry3d T_c1_w, T_c2_w;
};

TwoViews twoViews(const Eigen::Vector3d& baseline_world) {
  Vector6d xi;
  xi << 0.1, -0.2, 0.05, 0.02, -0.05, 0.03;
  TwoViews v;
  v.T_c1_w = expSE3(xi);
  Eigen::Isometry3d T_w_c2 = v.T_c1_w.inverse();
  T_w_c2.translation() += baseline_world;
  T_w_c2.linear() = T_w_c2.linear() * expSO3(Eigen::Vector3d(0.01, 0.08, -0.02));
  v.T_c2_w = T_w_c2.inverse();
  return v;
}

LineView observe(const Eigen::Matrix3d& K, const Eigen::Isometry3d& T_c_w, const Eigen::Vector3d& A,
                 const Eigen::Vector3d& B) {
  return LineView{T_c_w, (K * (T_c_w * A)).hnormalized(), (K * (T_c_w * B)).hnormalized()};
}

TEST(LineTriangulation, RecoversKnownLinesExactly) {
  const Eigen::Matrix3d K = testK();
  const TwoViews v = twoViews({0.5, 0.1, 0.05});
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> lateral(-2.0, 2.0), depth(3.0, 8.0);
  int triangulated = 0;
  for (int i = 0; i < 40; ++i) {
    const Eigen::Vector3d A = v.T_c1_w.inverse() * Eigen::Vector3d(lateral(rng), lateral(rng), depth(rng));
    const Eigen::Vector3d B = v.T_c1_w.inverse() * Eigen::Vector3d(lateral(rng), lateral(rng), depth(rng));
    // View 2 sees a different part of the same line.
    const auto result = triangulateLine(K, observe(K, v.T_c1_w, A, B),
                                        observe(K, v.T_c2_w, A + 0.2 * (B - A), B + 0.3 * (B - A)));
    if (!result) continue;  // a few random lines are near-degenerate
    ++triangulated;
    EXPECT_LT(sameLineError(result->line_world, PluckerLine::fromPoints(A, B)), 1e-9);
    EXPECT_NEAR(result->line_world.d.norm(), 1.0, 1e-12);
    EXPECT_LT((result->start_world - A).norm(), 1e-7);
    EXPECT_LT((result->end_world - B).norm(), 1e-7);
  }
  EXPECT_GE(triangulated, 30);
}

TEST(LineTriangulation, RejectsDegeneratePairs) {
  const Eigen::Matrix3d K = testK();
  const TwoViews v = twoViews({0.5, 0.0, 0.0});
  const Eigen::Isometry3d T_w_c1 = v.T_c1_w.inverse();
  const Eigen::Isometry3d T_w_c2 = v.T_c2_w.inverse();
  // A line in the epipolar plane: it contains a point and the baseline direction,
  // so both back-projected planes are the same plane.
  const Eigen::Vector3d P = T_w_c1 * Eigen::Vector3d(0.3, 0.4, 5.0);
  const Eigen::Vector3d baseline = T_w_c2.translation() - T_w_c1.translation();
  EXPECT_FALSE(triangulateLine(K, observe(K, v.T_c1_w, P, P + baseline),
                               observe(K, v.T_c2_w, P, P + baseline)));
  // Zero baseline: the same view twice.
  const Eigen::Vector3d A = T_w_c1 * Eigen::Vector3d(-0.5, -1, 4), B = T_w_c1 * Eigen::Vector3d(0.3, 1, 5);
  EXPECT_FALSE(triangulateLine(K, observe(K, v.T_c1_w, A, B), observe(K, v.T_c1_w, A, B)));
  // A line behind the cameras observed through the mirrored pixels.
  const Eigen::Vector3d Ab = T_w_c1 * Eigen::Vector3d(0.5, 1, -4), Bb = T_w_c1 * Eigen::Vector3d(-0.3, -1, -5);
  EXPECT_FALSE(triangulateLine(K, observe(K, v.T_c1_w, Ab, Bb), observe(K, v.T_c2_w, Ab, Bb)));
  // Non-finite or zero-length input.
  LineView nan_view = observe(K, v.T_c1_w, A, B);
  nan_view.start.x() = NAN;
  EXPECT_FALSE(triangulateLine(K, nan_view, observe(K, v.T_c2_w, A, B)));
  LineView point_view = observe(K, v.T_c1_w, A, A);
  EXPECT_FALSE(triangulateLine(K, point_view, observe(K, v.T_c2_w, A, B)));
  // The well-posed pair of the same line succeeds (the rejections are not blanket).
  EXPECT_TRUE(triangulateLine(K, observe(K, v.T_c1_w, A, B), observe(K, v.T_c2_w, A, B)));
}

TEST(LineTriangulation, DualPluckerMatrixGivesPlaneIntersection) {
  // Planes x = 1 and y = 2 meet in the line through (1, 2, 0) along z.
  const Eigen::Vector4d pi1(1, 0, 0, -1), pi2(0, 1, 0, -2);
  const PluckerLine L = lineFromDualPlucker(dualPluckerMatrix(pi1, pi2));
  EXPECT_LT(sameLineError(L, PluckerLine::fromPoints({1, 2, 0}, {1, 2, 1})), 1e-15);
}

TEST(SegmentTrimming, ExtentIsTheUnionOfTheObservedParts) {
  const Eigen::Matrix3d K = testK();
  const Eigen::Vector3d A(-2.0, 0.5, 6.0), B(2.0, -0.5, 7.0);
  const PluckerLine L = PluckerLine::fromPoints(A, B);
  const TwoViews v = twoViews({0.4, 0.0, 0.1});
  auto at = [&](double f) { return A + f * (B - A); };
  // View 1 sees 10 %..60 % of the segment, view 2 sees 30 %..85 %.
  const LineView o1 = observe(K, v.T_c1_w, at(0.1), at(0.6));
  const LineView o2 = observe(K, v.T_c2_w, at(0.85), at(0.3));  // reversed direction
  const auto trimmed = trimSegment(L, K, {{o1.T_camera_world, o1.start, o1.end}, {o2.T_camera_world, o2.start, o2.end}});
  ASSERT_TRUE(trimmed.has_value());
  // The extent runs along L.d: from 10 % to 85 %.
  EXPECT_LT((trimmed->start_world - at(0.1)).norm(), 1e-9);
  EXPECT_LT((trimmed->end_world - at(0.85)).norm(), 1e-9);
  // The extent follows the line's direction: reversing the line swaps the ends.
  const auto reversed = trimSegment(PluckerLine{-L.m, -L.d}, K, {{o1.T_camera_world, o1.start, o1.end}});
  ASSERT_TRUE(reversed.has_value());
  EXPECT_LT((reversed->start_world - at(0.6)).norm(), 1e-9);
  EXPECT_LT((reversed->end_world - at(0.1)).norm(), 1e-9);
  // No usable observation.
  EXPECT_FALSE(trimSegment(L, K, {}).has_value());
}

}  // namespace
}  // namespace lvslam::visual
