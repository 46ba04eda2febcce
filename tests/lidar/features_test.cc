// PCA descriptors, MULLS classes and primary directions on synthetic primitives.
#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "lidar/synthetic_lidar.h"
#include "lvslam/lidar/feature_extraction.h"
#include "lvslam/lidar/preprocess.h"

namespace lvslam::lidar {
namespace {

std::vector<Eigen::Vector3f> grid(const Eigen::Vector3f& origin, const Eigen::Vector3f& u, const Eigen::Vector3f& v,
                                  int nu, int nv, float step) {
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) points.push_back(origin + step * (i * u + j * v));
  return points;
}

FeatureClass classOf(const std::vector<Eigen::Vector3f>& points, Eigen::Vector3f& direction) {
  const auto cls = classifyShape(shapeOf(points), FeatureConfig{}, direction);
  EXPECT_TRUE(cls.has_value());
  return cls.value_or(FeatureClass::kGround);
}

TEST(LocalShape, DescriptorsOfAPlaneALineAndABlob) {
  const auto plane = shapeOf(grid({0, 0, 0}, Eigen::Vector3f::UnitX(), Eigen::Vector3f::UnitY(), 10, 10, 0.1f));
  EXPECT_NEAR(plane.planarity, 1.0f, 1e-4);
  EXPECT_NEAR(plane.curvature, 0.0f, 1e-6);
  EXPECT_NEAR(std::abs(plane.normal.z()), 1.0f, 1e-5);
  const auto line = shapeOf(grid({0, 0, 0}, Eigen::Vector3f(1, 1, 0).normalized(), Eigen::Vector3f::UnitZ(), 12, 1, 0.1f));
  EXPECT_NEAR(line.linearity, 1.0f, 1e-5);
  EXPECT_NEAR(std::abs(line.line_direction.dot(Eigen::Vector3f(1, 1, 0).normalized())), 1.0f, 1e-5);
  // The 8 corners of a cube: all eigenvalues equal, curvature 1/3.
  std::vector<Eigen::Vector3f> cube;
  for (int i = 0; i < 8; ++i) cube.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const auto blob = shapeOf(cube);
  EXPECT_NEAR(blob.curvature, 1.0f / 3.0f, 1e-5);
  EXPECT_NEAR(blob.linearity, 0.0f, 1e-5);
  EXPECT_FALSE(shapeOf(std::vector<Eigen::Vector3f>(5, Eigen::Vector3f(1, 2, 3))).valid);  // no spread
}

TEST(ClassifyShape, PlanesLinesAndCornersGetTheirMullsClass) {
  Eigen::Vector3f d;
  const Eigen::Vector3f x = Eigen::Vector3f::UnitX(), y = Eigen::Vector3f::UnitY(), z = Eigen::Vector3f::UnitZ();
  EXPECT_EQ(classOf(grid({5, 0, 0}, y, z, 8, 8, 0.1f), d), FeatureClass::kFacade);
  EXPECT_NEAR(std::abs(d.x()), 1.0f, 1e-4);
  EXPECT_EQ(classOf(grid({0, 0, 3}, x, y, 8, 8, 0.1f), d), FeatureClass::kRoof);
  EXPECT_NEAR(std::abs(d.z()), 1.0f, 1e-4);
  EXPECT_EQ(classOf(grid({1, 1, 0}, z, x, 15, 1, 0.1f), d), FeatureClass::kPillar);
  EXPECT_NEAR(std::abs(d.z()), 1.0f, 1e-4);
  EXPECT_EQ(classOf(grid({1, 1, 3}, y, x, 15, 1, 0.1f), d), FeatureClass::kBeam);
  EXPECT_NEAR(std::abs(d.y()), 1.0f, 1e-4);
  // Three faces of a box meeting at a corner: no dominant direction.
  std::vector<Eigen::Vector3f> corner;
  for (const auto& face : {grid({0, 0, 0}, x, y, 4, 4, 0.1f), grid({0, 0, 0}, y, z, 4, 4, 0.1f),
                           grid({0, 0, 0}, z, x, 4, 4, 0.1f)})
    corner.insert(corner.end(), face.begin(), face.end());
  EXPECT_EQ(classOf(corner, d), FeatureClass::kVertex);
  // A 45-degree slope is neither facade nor roof.
  EXPECT_FALSE(classifyShape(shapeOf(grid({0, 0, 0}, x, Eigen::Vector3f(0, 1, 1).normalized(), 8, 8, 0.1f)),
                             FeatureConfig{}, d));
}

TEST(ExtractFeatures, ScannedFloorWallAndPoleAreGroundFacadeAndPillar) {
  testing::SyntheticScene scene;
  scene.planes = {{Eigen::Vector3d::UnitZ(), 0.0}, {Eigen::Vector3d::UnitX(), 8.0}};
  scene.poles = {{{3.0, 2.0}, 0.15, 0.0, 5.0}};
  testing::SyntheticSensor sensor;
  sensor.columns = 1024;
  const Eigen::Isometry3d T_world_lidar = makePose(Eigen::Quaterniond::Identity(), Eigen::Vector3d(0, 0, 1.2));
  const LidarScan scan = testing::castScan(scene, [&](double) { return T_world_lidar; }, 0.0, sensor);
  // PCA at every non-ground point, or at one candidate per 0.3 m voxel.
  for (const double candidate_voxel : {0.0, 0.3}) {
    LidarOdometryConfig config;
    config.features.candidate_voxel = candidate_voxel;
    const auto features = extractFeatures(cropAndDownsample(scan, config.preprocess, config.features.neighbour_radius), config.ground, config.features);
    std::map<std::string, std::pair<int, int>> right_of;  // surface -> (right class and direction, total)
    for (const FeaturePoint& fp : features) {
      const Eigen::Vector3f w = (T_world_lidar.cast<float>() * fp.p);
      const bool on_pole = (w.head<2>() - Eigen::Vector2f(3, 2)).norm() < 0.2f && w.z() > 0.1f;
      const std::string surface = on_pole ? "pole" : std::abs(w.z()) < 0.01f ? "floor" : "wall";
      const FeatureClass expected = on_pole ? FeatureClass::kPillar
                                    : surface == "floor" ? FeatureClass::kGround : FeatureClass::kFacade;
      const Eigen::Vector3f axis = on_pole || surface == "floor" ? Eigen::Vector3f::UnitZ() : Eigen::Vector3f::UnitX();
      auto& [right, total] = right_of[surface];
      ++total;
      right += fp.cls == expected && std::abs(fp.direction.dot(axis)) > 0.98f ? 1 : 0;
    }
    // The pole's foot and top mix with the floor and the end of the view.
    for (const auto& [surface, share] : std::map<std::string, double>{{"floor", 0.9}, {"wall", 0.9}, {"pole", 0.8}}) {
      const auto [right, total] = right_of[surface];
      EXPECT_GE(total, 5) << surface << " candidate_voxel " << candidate_voxel;
      EXPECT_GE(right, share * total) << surface << " candidate_voxel " << candidate_voxel;
    }
  }
}

TEST(Preprocess, DropsInvalidAndOutOfRangeReturns) {
  LidarScan scan;
  scan.has_time = true;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (const Eigen::Vector3f& p : {Eigen::Vector3f(nan, 0, 0), Eigen::Vector3f(0.1f, 0, 0), Eigen::Vector3f(500, 0, 0),
                                   Eigen::Vector3f(5, 0, 0), Eigen::Vector3f(5.01f, 0, 0), Eigen::Vector3f(0, 7, 0)})
    scan.points.push_back({p, 0.0f, 0.01f, 0});
  scan.points.push_back({Eigen::Vector3f(0, 0, 9), 0.0f, 1e6f, 0});  // corrupt time
  const auto kept = cropAndDownsample(scan, PreprocessConfig{}, 0.0);
  ASSERT_EQ(kept.size(), 2u);  // (5,0,0) and (5.01,0,0) share a voxel
  EXPECT_EQ(kept[0].p, Eigen::Vector3f(5, 0, 0));
  EXPECT_EQ(kept[1].p, Eigen::Vector3f(0, 7, 0));
  EXPECT_FLOAT_EQ(kept[1].time, 0.01f);
}

}  // namespace
}  // namespace lvslam::lidar
