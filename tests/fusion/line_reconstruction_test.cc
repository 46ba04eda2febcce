#include "lvslam/fusion/line_reconstruction.h"

#include <random>

#include <gtest/gtest.h>

#include "fusion/test_rig.h"

namespace lvslam::fusion {
namespace {

using testing::testCamera;

ImageSegment segmentOf(const PinholeCamera& cam, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return {*cam.project(a), *cam.project(b)};
}

// Planar feature points of the wall z = depth, on a grid, normals facing
// either way (PCA gives normals without a sign).
void addWall(std::vector<SphereFeature>& out, double depth, double spacing, double noise, std::mt19937& rng) {
  std::normal_distribution<double> g(0.0, noise);
  for (double x = -3.0; x <= 3.0; x += spacing) {
    for (double y = -2.0; y <= 2.0; y += spacing) {
      SphereFeature f;
      f.p_camera = Eigen::Vector3d(x, y, depth + g(rng));
      f.direction_camera = Eigen::Vector3d(g(rng) * 0.02, g(rng) * 0.02, (out.size() % 2) ? 1.0 : -1.0).normalized();
      f.shape = FeatureShape::kPlanar;
      f.id = out.size();
      out.push_back(f);
    }
  }
}

// Linear feature points along a vertical pole at (x, *, z).
void addPole(std::vector<SphereFeature>& out, double x, double z, double y0, double y1, double noise,
             std::mt19937& rng, std::uint64_t id_offset) {
  std::normal_distribution<double> g(0.0, noise);
  for (double y = y0; y <= y1; y += 0.01) {
    SphereFeature f;
    f.p_camera = Eigen::Vector3d(x + g(rng), y, z + g(rng));
    f.direction_camera = Eigen::Vector3d(g(rng) * 0.03, 1.0, g(rng) * 0.03).normalized();
    f.shape = FeatureShape::kLinear;
    f.id = id_offset + out.size();
    out.push_back(f);
  }
}

TEST(LineReconstruction, TextureLineOnAWallIsThePlaneIntersection) {
  std::mt19937 rng(1);
  std::vector<SphereFeature> features;
  addWall(features, 5.0, 0.03, 0.0, rng);
  const SphereIndex index(features);
  const PinholeCamera cam = testCamera();
  const Eigen::Vector3d A(0.5, -1.0, 5.0), B(0.5, 1.2, 5.0);  // a door frame edge painted on the wall
  RejectReason why;
  const auto line = LineReconstructor(cam, FusionConfig{}).reconstruct(segmentOf(cam, A, B), features, index, &why);
  ASSERT_TRUE(line.has_value()) << static_cast<int>(why);
  EXPECT_EQ(line->kind, FusionLineKind::kPlaneIntersection);
  EXPECT_LT((line->A - A).norm(), 1e-9);
  EXPECT_LT((line->B - B).norm(), 1e-9);
  EXPECT_TRUE(line->linear_feature_ids.empty());
}

TEST(LineReconstruction, NoisyWallGivesCentimetreEndpoints) {
  std::mt19937 rng(2);
  std::vector<SphereFeature> features;
  addWall(features, 4.0, 0.03, 0.01, rng);  // 1 cm range noise
  const SphereIndex index(features);
  const PinholeCamera cam = testCamera();
  const Eigen::Vector3d A(-1.0, 0.3, 4.0), B(1.5, 0.6, 4.0);
  const auto line = LineReconstructor(cam, FusionConfig{}).reconstruct(segmentOf(cam, A, B), features, index);
  ASSERT_TRUE(line.has_value());
  EXPECT_LT((line->A - A).norm(), 0.02);
  EXPECT_LT((line->B - B).norm(), 0.02);
}

TEST(LineReconstruction, PoleInFrontOfAWallIsTheLinearCluster) {
  std::mt19937 rng(3);
  std::vector<SphereFeature> features;
  addWall(features, 9.0, 0.08, 0.0, rng);
  const std::size_t wall_points = features.size();
  addPole(features, 1.0, 4.0, -1.5, 1.5, 0.005, rng, 0);
  const SphereIndex index(features);
  const PinholeCamera cam = testCamera();
  const Eigen::Vector3d A(1.0, -1.0, 4.0), B(1.0, 1.0, 4.0);
  RejectReason why;
  const auto line = LineReconstructor(cam, FusionConfig{}).reconstruct(segmentOf(cam, A, B), features, index, &why);
  ASSERT_TRUE(line.has_value()) << static_cast<int>(why);
  EXPECT_EQ(line->kind, FusionLineKind::kLinearCluster);
  EXPECT_GT(std::abs(line->direction.y()), std::cos(1.0 * M_PI / 180.0));
  EXPECT_LT((line->A - A).norm(), 0.02);
  EXPECT_LT((line->B - B).norm(), 0.02);
  ASSERT_FALSE(line->linear_feature_ids.empty());
  for (const auto id : line->linear_feature_ids) EXPECT_GE(id, wall_points);  // only pole points
}

TEST(LineReconstruction, SegmentWithNoLidarNearbyIsRejected) {
  std::mt19937 rng(4);
  std::vector<SphereFeature> features;
  addPole(features, -2.0, 4.0, -1.0, 1.0, 0.0, rng, 0);
  const SphereIndex index(features);
  const PinholeCamera cam = testCamera();
  RejectReason why;
  const auto line = LineReconstructor(cam, FusionConfig{})
                        .reconstruct(segmentOf(cam, {1.0, -1.0, 4.0}, {1.0, 1.0, 4.0}), features, index, &why);
  EXPECT_FALSE(line.has_value());
  EXPECT_EQ(why, RejectReason::kFarOnSphere);
}

TEST(LineReconstruction, TwoPolesAtDifferentDepthsBehindOneSegmentAreRejected) {
  std::mt19937 rng(5);
  std::vector<SphereFeature> features;
  addPole(features, 1.0, 4.0, 0.0, 1.2, 0.0, rng, 0);     // upper half near
  addPole(features, 1.5, 6.0, -1.8, 0.0, 0.0, rng, 0);    // lower half far, same image column
  const SphereIndex index(features);
  const PinholeCamera cam = testCamera();
  RejectReason why;
  const auto line = LineReconstructor(cam, FusionConfig{})
                        .reconstruct(segmentOf(cam, {1.0, -1.0, 4.0}, {1.0, 1.0, 4.0}), features, index, &why);
  EXPECT_FALSE(line.has_value());
  EXPECT_EQ(why, RejectReason::kDepthInconsistent);
}

TEST(LineReconstruction, ShortSegmentsAreRejected) {
  std::vector<SphereFeature> features(1);
  features[0].p_camera = Eigen::Vector3d(0, 0, 1);
  const SphereIndex index(features);
  RejectReason why;
  EXPECT_FALSE(LineReconstructor(testCamera(), FusionConfig{})
                   .reconstruct({{100, 100}, {110, 100}}, features, index, &why)
                   .has_value());
  EXPECT_EQ(why, RejectReason::kTooShort);
}

}  // namespace
}  // namespace lvslam::fusion
