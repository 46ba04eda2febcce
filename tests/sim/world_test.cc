#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "lvslam/sim/counter_random.h"
#include "lvslam/sim/scenario.h"

namespace lvslam::sim {
namespace {

Primitive makePrimitive(PrimitiveKind kind, const Eigen::Vector3d& center, const Eigen::Vector3d& half) {
  Primitive p;
  p.kind = kind;
  p.center = center;
  p.half = half;
  p.R = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return p;
}

TEST(Primitive, RayMeetsEachKindWhereGeometrySays) {
  const Eigen::Vector3d origin(0, 0, 0), down(0, 0, -1);
  // A rectangle 2 m below, tilted about z only: the ray meets it at 2 m, normal up.
  auto rect = intersect(makePrimitive(PrimitiveKind::kRect, {0, 0, -2}, {1, 1, 0}), origin, down, 1e9);
  ASSERT_TRUE(rect);
  EXPECT_NEAR(rect->distance, 2.0, 1e-12);
  EXPECT_NEAR(rect->normal.z(), 1.0, 1e-12);
  // Box centred 5 m below with half height 1: top face at 4 m.
  auto box = intersect(makePrimitive(PrimitiveKind::kBox, {0, 0, -5}, {0.5, 0.7, 1.0}), origin, down, 1e9);
  ASSERT_TRUE(box);
  EXPECT_NEAR(box->distance, 4.0, 1e-12);
  // Cylinder along z centred 3 m ahead on x, radius 0.5: side at 2.5 m.
  auto cyl = intersect(makePrimitive(PrimitiveKind::kCylinder, {3, 0, 0}, {0.5, 0.5, 1.0}), origin, {1, 0, 0}, 1e9);
  ASSERT_TRUE(cyl);
  EXPECT_NEAR(cyl->distance, 2.5, 1e-12);
  EXPECT_NEAR(cyl->normal.x(), -1.0, 1e-12);
  auto sphere = intersect(makePrimitive(PrimitiveKind::kSphere, {0, 4, 0}, {1, 1, 1}), origin, {0, 1, 0}, 1e9);
  ASSERT_TRUE(sphere);
  EXPECT_NEAR(sphere->distance, 3.0, 1e-12);
  // Beyond t_max or pointing away: no hit.
  EXPECT_FALSE(intersect(makePrimitive(PrimitiveKind::kSphere, {0, 4, 0}, {1, 1, 1}), origin, {0, 1, 0}, 2.5));
  EXPECT_FALSE(intersect(makePrimitive(PrimitiveKind::kSphere, {0, 4, 0}, {1, 1, 1}), origin, {0, -1, 0}, 1e9));
}

TEST(Primitive, DistanceToSurfaceIsExact) {
  const Primitive box = makePrimitive(PrimitiveKind::kBox, {0, 0, 0}, {1, 2, 3});
  EXPECT_NEAR(distanceToSurface(box, {0, 0, 0}), 1.0, 1e-12);                 // inside: nearest face
  EXPECT_NEAR(distanceToSurface(box, box.R * Eigen::Vector3d(1, 0, 5)), 2.0, 1e-12);
  const Primitive cyl = makePrimitive(PrimitiveKind::kCylinder, {0, 0, 0}, {1, 1, 1});
  EXPECT_NEAR(distanceToSurface(cyl, {3, 0, 0}), 2.0, 1e-12);
  EXPECT_NEAR(distanceToSurface(cyl, {4, 0, 5}), 5.0, 1e-12);                  // corner: hypot(3, 4)
}

// The BVH must find exactly what testing every primitive finds.
TEST(World, RaycastMatchesBruteForceAndLandsOnSurfaces) {
  const Scenario scenario = makeScenario("gate", SimOptions{});
  const World& world = scenario.world;
  CounterRandom rng(7, RandomStream::kScene, 99);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d origin(rng.uniform(-10, 25), rng.uniform(-12, 12), rng.uniform(0.3, 3));
    const Eigen::Vector3d dir(rng.normal(), rng.normal(), rng.normal());
    const auto hit = world.raycast(origin, dir, 150.0);
    double brute = 150.0;
    for (const auto& p : world.primitives())
      if (auto h = intersect(p, origin, dir.normalized(), brute)) brute = h->distance;
    if (!hit) {
      EXPECT_EQ(brute, 150.0);
      continue;
    }
    ++hits;
    EXPECT_NEAR(hit->distance, brute, 1e-9);
    EXPECT_LT(world.distanceToSurface(origin + hit->distance * dir.normalized()), 1e-9);
    EXPECT_GE(hit->albedo, 0.0);
    EXPECT_LE(hit->albedo, 1.0);
  }
  EXPECT_GT(hits, 1000);
}

TEST(World, EdgesIncludeWallFloorBoundariesAndLieOnSurfaces) {
  const Scenario scenario = makeScenario("room", SimOptions{});
  const auto edges = scenario.world.edges();
  bool south_floor_edge = false;
  for (const WorldEdge& e : edges) {
    const bool along_x = std::abs(e.a.y()) < 1e-12 && std::abs(e.b.y()) < 1e-12 && std::abs(e.a.z()) < 1e-12 &&
                         std::abs(e.b.z()) < 1e-12 && std::abs(std::abs(e.b.x() - e.a.x()) - 10.0) < 1e-12;
    south_floor_edge = south_floor_edge || along_x;
    EXPECT_LT(scenario.world.distanceToSurface(0.5 * (e.a + e.b)), 1e-9);
  }
  EXPECT_TRUE(south_floor_edge);
  EXPECT_GT(edges.size(), 1000u);  // furniture, frames and books give many lines
}

// The twins scene's room B is room A moved 14 m: every ray from a point of
// room A meets what the same ray from the same point of room B meets, at the
// same range, and (but where rounding of the shift moves a hit across a
// texel's border) the same albedo; except through the opening. Its
// drive keeps the camera and the LiDAR clear of every surface.
TEST(World, TwinRoomsAreExactCopiesAndTheDriveStaysInFreeSpace) {
  SimOptions options;
  options.duration = 140.0;
  const Scenario scenario = makeScenario("twins", options);
  const Eigen::Vector3d shift(14.0, 0.0, 0.0);
  CounterRandom rng(7, RandomStream::kScene, 1);
  int compared = 0, same_albedo = 0;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d origin(rng.uniform(1.0, 9.0), rng.uniform(1.0, 7.0), rng.uniform(0.3, 2.7));
    const Eigen::Vector3d dir(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
    const auto a = scenario.world.raycast(origin, dir);
    const auto b = scenario.world.raycast(origin + shift, dir);
    ASSERT_TRUE(a && b);
    if ((origin + a->distance * dir.normalized()).y() > 7.99) continue;  // through the opening
    EXPECT_NEAR(a->distance, b->distance, 1e-9);
    EXPECT_TRUE(a->normal.isApprox(b->normal, 1e-9));
    same_albedo += std::abs(a->albedo - b->albedo) < 1e-9;
    ++compared;
  }
  EXPECT_GT(compared, 1800);
  EXPECT_GT(same_albedo, 0.99 * compared);
  double clearance = 1e9;
  for (double t = 0.0; t < options.duration; t += 0.05)
    for (const Eigen::Isometry3d& T : {scenario.T_world_camera(t), scenario.T_world_lidar(t)})
      clearance = std::min(clearance, scenario.world.distanceToSurface(T.translation()));
  EXPECT_GT(clearance, 0.3);  // a small robot's half width
}

}  // namespace
}  // namespace lvslam::sim
