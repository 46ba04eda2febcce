#include "lvslam/core/plucker_line.h"

#include <gtest/gtest.h>

#include "lvslam/core/se3.h"

namespace lvslam {
namespace {

Eigen::Isometry3d somePose() {
  Vector6d xi;
  xi << 0.7, -1.1, 2.3, 0.4, -0.9, 0.3;
  return expSE3(xi);
}

TEST(PluckerLine, FromPointsHasPaperMomentAndDirection) {
  const Eigen::Vector3d A(1.0, 2.0, 3.0), B(-2.0, 0.5, 4.0);
  const PluckerLine L = PluckerLine::fromPoints(A, B);
  EXPECT_TRUE(L.m.isApprox(A.cross(B)));
  EXPECT_TRUE(L.d.isApprox(B - A));
  EXPECT_NEAR(L.m.dot(L.d), 0.0, 1e-12);
  EXPECT_TRUE(L.isValid());
  EXPECT_NEAR(L.distanceTo(A), 0.0, 1e-12);
  EXPECT_NEAR(L.distanceTo(0.3 * A + 0.7 * B), 0.0, 1e-12);
  EXPECT_NEAR(L.distanceTo(A + L.d.cross(Eigen::Vector3d::UnitZ()).normalized() * 2.0), 2.0, 1e-12);
}

TEST(PluckerLine, TransformMatchesTransformingTheTwoPoints) {
  const Eigen::Vector3d A(1.0, 2.0, 3.0), B(-2.0, 0.5, 4.0);
  const Eigen::Isometry3d T_a_b = somePose();
  const PluckerLine direct = PluckerLine::fromPoints(T_a_b * A, T_a_b * B);
  const PluckerLine moved = PluckerLine::fromPoints(A, B).transformed(T_a_b);
  EXPECT_LT((direct.vector() - moved.vector()).norm(), 1e-12);
  const Vector6d by_matrix = pluckerTransformMatrix(T_a_b) * PluckerLine::fromPoints(A, B).vector();
  EXPECT_LT((by_matrix - direct.vector()).norm(), 1e-12);
  // Transform and inverse transform are a round trip.
  const PluckerLine back = moved.transformed(T_a_b.inverse());
  EXPECT_LT((back.vector() - PluckerLine::fromPoints(A, B).vector()).norm(), 1e-12);
}

TEST(PluckerLine, ClosestPointsAreOnTheLineAndPerpendicular) {
  const PluckerLine L = PluckerLine::fromPoints({0.0, 1.0, 5.0}, {1.0, 1.0, 5.0});
  EXPECT_TRUE(L.closestPointToOrigin().isApprox(Eigen::Vector3d(0.0, 1.0, 5.0)));
  EXPECT_TRUE(L.closestPointTo({3.0, 7.0, -2.0}).isApprox(Eigen::Vector3d(3.0, 1.0, 5.0)));
  // A camera ray from the origin through (2, 1, 5) meets the line at x = 2.
  Eigen::Vector3d p;
  ASSERT_TRUE(L.closestPointToRay(Eigen::Vector3d::Zero(), {2.0, 1.0, 5.0}, p));
  EXPECT_LT((p - Eigen::Vector3d(2.0, 1.0, 5.0)).norm(), 1e-12);
  // A skew ray: the result is on the line and the connecting segment is
  // perpendicular to both.
  const Eigen::Vector3d o(0.5, -1.0, 0.0), v(0.1, 0.3, 1.0);
  ASSERT_TRUE(L.closestPointToRay(o, v, p));
  EXPECT_NEAR(L.distanceTo(p), 0.0, 1e-12);
  const Eigen::Vector3d q = o + v * (v.dot(p - o) / v.squaredNorm());
  EXPECT_NEAR((p - q).dot(L.d), 0.0, 1e-12);
  EXPECT_NEAR((p - q).dot(v), 0.0, 1e-12);
  // A ray parallel to the line has no unique closest point.
  EXPECT_FALSE(L.closestPointToRay(Eigen::Vector3d::Zero(), L.d, p));
}

TEST(PluckerLine, InvalidLinesAreDetected) {
  EXPECT_FALSE((PluckerLine{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d::Zero()}.isValid()));
  EXPECT_FALSE((PluckerLine{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 0, 0)}.isValid()));
  EXPECT_FALSE((PluckerLine{Eigen::Vector3d(NAN, 0, 0), Eigen::Vector3d(0, 1, 0)}.isValid()));
  EXPECT_TRUE((PluckerLine{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)}.isValid()));
}

TEST(PluckerLine, NormalizedKeepsTheLine) {
  const PluckerLine L = PluckerLine::fromPoints({1.0, 2.0, 3.0}, {4.0, -2.0, 9.0});
  const PluckerLine n = L.normalized();
  EXPECT_NEAR(n.d.norm(), 1.0, 1e-15);
  EXPECT_NEAR(n.distanceTo({1.0, 2.0, 3.0}), 0.0, 1e-12);
  EXPECT_TRUE(n.closestPointToOrigin().isApprox(L.closestPointToOrigin()));
}

}  // namespace
}  // namespace lvslam
