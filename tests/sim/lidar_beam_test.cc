#include <cmath>

#include <gtest/gtest.h>

#include "lvslam/sim/lidar_beam.h"
#include "lvslam/sim/scene_builder.h"

namespace lvslam::sim {
namespace {

// Local axes of a rectangle facing the x axis: its x along world y, its y along world z.
Eigen::Matrix3d facingX() {
  Eigen::Matrix3d R;
  R.col(0) = Eigen::Vector3d::UnitY();
  R.col(1) = Eigen::Vector3d::UnitZ();
  R.col(2) = Eigen::Vector3d::UnitX();
  return R;
}

// A near panel at x = 5 covering [y0, y1] x [z0, z1] in front of a wall at x = far.
World edgeWorld(double y0, double y1, double z0, double z1, double far, double far_albedo = 0.5) {
  SceneBuilder scene(1);
  const int grey = scene.texture(Texture{TextureKind::kPlain, 0.5, 0.5, 1.0, 0.0, 0});
  const int wall = scene.texture(Texture{TextureKind::kPlain, far_albedo, far_albedo, 1.0, 0.0, 0});
  scene.rect({5.0, 0.5 * (y0 + y1), 0.5 * (z0 + z1)}, facingX(), 0.5 * (y1 - y0), 0.5 * (z1 - z0), grey);
  scene.rect({far, 0.0, 0.0}, facingX(), 3.0, 3.0, wall);
  return scene.build();
}

const std::vector<Primitive> kNobody;
const Eigen::Vector3d kOrigin = Eigen::Vector3d::Zero();

// The pulse along `dir` from the origin as a footprint (draw 0.9: glass reflects it away).
std::optional<WorldHit> footprintOf(const World& world, const Eigen::Vector3d& dir) {
  return BeamCaster(world, BeamModel{}).castFootprint(kOrigin, dir, kNobody, 100.0, 0.9);
}

// The footprint straddles the panel's edge: two of its four samples on the
// panel (5 m), two on the wall (6 m), equal echoes: the sensor reports the
// mean, 5.5 m, a point on neither surface.
TEST(LidarBeam, MixedReturnLiesBetweenTheTwoSurfaces) {
  const World world = edgeWorld(0.0, 1.0, -1.0, 1.0, 6.0);
  const auto hit = footprintOf(world, Eigen::Vector3d::UnitX());
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->distance, 5.5, 1e-9);
  // One sample of four on the panel (a corner): a quarter of the way.
  const World corner = edgeWorld(0.0, 1.0, 0.0, 1.0, 6.0);
  EXPECT_NEAR(footprintOf(corner, Eigen::Vector3d::UnitX())->distance, 5.75, 1e-9);
  // A single ray sees one surface or the other, never between.
  const Eigen::Vector3d just_inside(1.0, 0.001, 0.0);
  const auto ray = BeamCaster(world, BeamModel{}).castRay(kOrigin, just_inside.normalized(), kNobody, 100.0, 0.9);
  ASSERT_TRUE(ray);
  EXPECT_NEAR(ray->distance, 5.0 * just_inside.norm(), 1e-9);
}

// Echoes farther apart than the pulse length are separate returns: the
// sensor reports the strongest (the brighter panel), not a mean.
TEST(LidarBeam, SeparateEchoesDoNotMix) {
  const auto cast = [](const World& world) { return footprintOf(world, Eigen::Vector3d::UnitX())->distance; };
  EXPECT_NEAR(cast(edgeWorld(0.0, 1.0, -1.0, 1.0, 8.0, 0.3)), 5.0, 1e-9);
  EXPECT_NEAR(cast(edgeWorld(0.0, 1.0, -1.0, 1.0, 8.0, 0.9)), 8.0, 1e-9);
  // Within the pulse length the brighter echo weighs more: (5 * 0.5 + 6 * 0.9) / 1.4.
  EXPECT_NEAR(cast(edgeWorld(0.0, 1.0, -1.0, 1.0, 6.0, 0.9)), (5.0 * 0.5 + 6.0 * 0.9) / 1.4, 1e-9);
}

// A pane of glass at 3 m before a wall at 6 m: the camera's ray passes it,
// the pulse gives no return, or (draw below glass_return) the wall's.
TEST(LidarBeam, GlassGivesNoReturnOrTheSurfaceBehind) {
  SceneBuilder scene(1);
  const int grey = scene.texture(Texture{TextureKind::kPlain, 0.5, 0.5, 1.0, 0.0, 0});
  scene.glassPane({3.0, 0.0, 0.0}, facingX(), 2.0, 2.0, grey);
  scene.rect({6.0, 0.0, 0.0}, facingX(), 3.0, 3.0, grey);
  const World world = scene.build();
  ASSERT_TRUE(world.primitives()[0].glass);
  EXPECT_NEAR(world.raycast(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX())->distance, 3.0, 1e-12);
  EXPECT_NEAR(world.raycast(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 1e9, 0.0, true)->distance, 6.0, 1e-12);
  const BeamModel model;
  const BeamCaster beam(world, model);
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX();
  EXPECT_FALSE(beam.castRay(kOrigin, x, kNobody, 100.0, model.glass_return));
  EXPECT_FALSE(beam.castFootprint(kOrigin, x, kNobody, 100.0, model.glass_return));
  for (const auto& behind : {beam.castRay(kOrigin, x, kNobody, 100.0, 0.0),
                             beam.castFootprint(kOrigin, x, kNobody, 100.0, 0.0)}) {
    ASSERT_TRUE(behind);
    EXPECT_NEAR(behind->distance, 6.0, 1e-9);
  }
}

TEST(LidarBeam, RangeNoiseGrowsWithRangeAndIncidence) {
  EXPECT_DOUBLE_EQ(rangeSigma(0.015, 0.0, 1.0, 40.0, 0.3), 0.015);  // the old constant model
  EXPECT_DOUBLE_EQ(rangeSigma(0.01, 0.001, 0.2, 20.0, 1.0), 0.03);
  EXPECT_DOUBLE_EQ(rangeSigma(0.01, 0.001, 0.2, 20.0, 0.5), 0.06);
  EXPECT_DOUBLE_EQ(rangeSigma(0.01, 0.001, 0.2, 20.0, 0.05), 0.15);  // capped at 1 / 0.2
}

}  // namespace
}  // namespace lvslam::sim
