#include "lvslam/fusion/line_geometry.h"

#include <cmath>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace lvslam::fusion {
namespace {

constexpr double kDeg = M_PI / 180.0;

TEST(LineGeometry, PlaneIntersectionIsTheExactLine) {
  // x = 2 and z = 5 meet in the line (2, t, 5).
  const Plane px{Eigen::Vector3d::UnitX(), -2.0};
  const Plane pz{Eigen::Vector3d::UnitZ(), -5.0};
  const auto line = intersectPlanes(px, pz, 1.0 * kDeg);
  ASSERT_TRUE(line.has_value());
  EXPECT_NEAR(std::abs(line->direction.y()), 1.0, 1e-15);
  EXPECT_LT((line->point - Eigen::Vector3d(2.0, 0.0, 5.0)).norm(), 1e-12);
}

TEST(LineGeometry, ObliquePlaneIntersectionSatisfiesBothPlanes) {
  const Plane a{Eigen::Vector3d(0.3, -0.5, 0.8).normalized(), 1.7};
  const Plane b{Eigen::Vector3d(-0.6, 0.1, 0.4).normalized(), -0.4};
  const auto line = intersectPlanes(a, b, 1.0 * kDeg);
  ASSERT_TRUE(line.has_value());
  for (double s : {-10.0, 0.0, 3.0}) {
    const Eigen::Vector3d x = line->point + s * line->direction;
    EXPECT_NEAR(a.signedDistance(x), 0.0, 1e-12);
    EXPECT_NEAR(b.signedDistance(x), 0.0, 1e-12);
  }
  EXPECT_FALSE(intersectPlanes(a, Plane{a.n, 3.0}, 1.0 * kDeg).has_value());  // parallel
}

TEST(LineGeometry, BackProjectedPlaneContainsBothRaysAndTheCentre) {
  const Eigen::Vector3d ra(0.2, 0.1, 1.0), rb(-0.3, 0.4, 1.0);
  const auto plane = backProjectedPlane(ra, rb);
  ASSERT_TRUE(plane.has_value());
  EXPECT_NEAR(plane->d, 0.0, 0.0);
  EXPECT_NEAR(plane->n.dot(ra), 0.0, 1e-15);
  EXPECT_NEAR(plane->n.dot(rb), 0.0, 1e-15);
  EXPECT_FALSE(backProjectedPlane(ra, 2.0 * ra).has_value());
}

TEST(LineGeometry, PlaneFromNormalsRecoversThePlaneDespiteFlippedNormals) {
  const Eigen::Vector3d n = Eigen::Vector3d(0.1, -0.2, 1.0).normalized();
  const double d = -4.0;
  std::vector<Eigen::Vector3d> pts, nrm;
  for (int i = 0; i < 20; ++i) {
    Eigen::Vector3d p(0.1 * i - 1.0, 0.07 * i * i - 2.0, 0.0);
    p.z() = (-d - n.x() * p.x() - n.y() * p.y()) / n.z();
    pts.push_back(p);
    nrm.push_back(i % 3 == 0 ? Eigen::Vector3d(-n) : n);
  }
  const auto plane = fitPlaneFromNormals(pts, nrm);
  ASSERT_TRUE(plane.has_value());
  const double sign = plane->n.dot(n) > 0 ? 1.0 : -1.0;
  EXPECT_LT((sign * plane->n - n).norm(), 1e-12);
  EXPECT_NEAR(sign * plane->d, d, 1e-12);
}

TEST(LineGeometry, ClosestPointOnLineToRayIsTheCommonPerpendicularFoot) {
  // Line x = 1, z = 4 along y; the ray through (0, 0.5, 1) meets it at y = 2.
  const Line3 line{Eigen::Vector3d(1.0, -3.0, 4.0), Eigen::Vector3d::UnitY()};
  const auto p = closestPointOnLineToRay(line, Eigen::Vector3d(0.25, 0.5, 1.0));
  ASSERT_TRUE(p.has_value());
  EXPECT_LT((*p - Eigen::Vector3d(1.0, 2.0, 4.0)).norm(), 1e-12);
  // A skew ray: the foot is where the common perpendicular meets the line.
  const auto q = closestPointOnLineToRay(line, Eigen::Vector3d(0.0, 0.0, 1.0));
  ASSERT_TRUE(q.has_value());
  EXPECT_LT((*q - Eigen::Vector3d(1.0, 0.0, 4.0)).norm(), 1e-12);
  EXPECT_FALSE(closestPointOnLineToRay(line, Eigen::Vector3d::UnitY()).has_value());
}

TEST(LineGeometry, RayPlaneIntersectionOnlyInFront) {
  const Plane wall{Eigen::Vector3d::UnitZ(), -5.0};
  const auto p = intersectRayPlane(Eigen::Vector3d(0.2, 0.0, 1.0), wall);
  ASSERT_TRUE(p.has_value());
  EXPECT_LT((*p - Eigen::Vector3d(1.0, 0.0, 5.0)).norm(), 1e-12);
  EXPECT_FALSE(intersectRayPlane(Eigen::Vector3d(0.0, 0.0, -1.0), wall).has_value());
}

TEST(LineGeometry, DominantClusterIgnoresSignAndOutliers) {
  std::vector<Eigen::Vector3d> dirs;
  const Eigen::Vector3d truth = Eigen::Vector3d(1.0, 0.2, 0.0).normalized();
  for (int i = 0; i < 7; ++i) {
    const Eigen::Vector3d d =
        Eigen::AngleAxisd((i - 3) * 1.0 * kDeg, Eigen::Vector3d::UnitZ()) * truth;  // symmetric spread
    dirs.push_back(i % 2 ? Eigen::Vector3d(-d) : d);
  }
  dirs.push_back(Eigen::Vector3d::UnitZ());
  dirs.push_back(Eigen::Vector3d(0.0, 1.0, 0.3).normalized());
  const DirectionCluster c = dominantDirectionCluster(dirs, 10.0 * kDeg);
  EXPECT_EQ(c.members.size(), 7u);
  EXPECT_NEAR(std::abs(c.mean_direction.dot(truth)), 1.0, 1e-12);
}

}  // namespace
}  // namespace lvslam::fusion
