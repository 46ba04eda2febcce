#include "lvslam/fusion/fusion_framework.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "lvslam/core/se3.h"
#include "lvslam/fusion/sphere_index.h"
#include "fusion/test_rig.h"

namespace lvslam::fusion {
namespace {

using testing::cameraFromLidar;
using testing::testCamera;

// The LiDAR drives along world x at 1 m/s, yawing at 0.2 rad/s.
Eigen::Isometry3d lidarPose(double t) {
  return makePose(expSO3(Eigen::Vector3d(0.0, 0.0, 0.2 * t)), Eigen::Vector3d(t, 0.0, 1.0));
}

// Features of world points as a scan starting at t0 measures them: each in
// the LiDAR frame at its own capture time.
std::vector<TimedFeature> measure(const std::vector<Eigen::Vector3d>& world, const std::vector<Eigen::Vector3d>& dirs,
                                  FeatureShape shape, double t0, std::uint64_t first_id) {
  std::vector<TimedFeature> out;
  for (std::size_t i = 0; i < world.size(); ++i) {
    const double t = t0 + 0.1 * static_cast<double>(i) / static_cast<double>(world.size());
    const Eigen::Isometry3d T = lidarPose(t);
    out.push_back({T.inverse() * world[i], T.linear().transpose() * dirs[i], shape, t, first_id + i});
  }
  return out;
}

ConstantVelocityMotion motionOfScan(double t0) { return {t0, lidarPose(t0), t0 + 0.1, lidarPose(t0 + 0.1)}; }

TEST(FeatureAccumulator, ScansMeasuredWhileMovingAgreeInTheCameraFrame) {
  FeatureAccumulator acc(5);
  const std::vector<Eigen::Vector3d> world{{6.0, 1.0, 1.5}}, dirs{{0.0, 0.0, 1.0}};
  for (int k = 0; k < 7; ++k) acc.addScan(measure(world, dirs, FeatureShape::kLinear, 0.1 * k, 0), motionOfScan(0.1 * k));
  EXPECT_EQ(acc.scans(), 5u);  // the current and the last four
  const Eigen::Isometry3d T_world_camera = lidarPose(0.65) * cameraFromLidar().inverse();
  const auto features = acc.inCameraFrame(T_world_camera);
  ASSERT_EQ(features.size(), 5u);
  const Eigen::Vector3d expected = T_world_camera.inverse() * world[0];
  // Poses of a constant yaw rate and speed are interpolated exactly up to the
  // chord-vs-arc difference of slerp+lerp over 0.1 s: well below a millimetre.
  for (const auto& f : features) EXPECT_LT((f.p_camera - expected).norm(), 1e-3);
}

// A wall 8 m ahead of the start (world x = 8) and a pole at (5, -1).
struct Scene {
  std::vector<Eigen::Vector3d> wall, wall_normals, pole, pole_dirs;
  Scene() {
    for (double y = -4.0; y <= 4.0; y += 0.04)
      for (double z = 0.0; z <= 3.0; z += 0.04) {
        wall.emplace_back(8.0, y, z);
        wall_normals.emplace_back(1.0, 0.0, 0.0);
      }
    for (double z = 0.0; z <= 3.0; z += 0.01) {
      pole.emplace_back(5.0, -1.0, z);
      pole_dirs.emplace_back(0.0, 0.0, 1.0);
    }
  }
};

TEST(FusionFramework, PoleBecomesALinearFusionLineAndFeedsItsDirectionBack) {
  const Scene scene;
  FusionFramework fusion(testCamera(), cameraFromLidar(), FusionConfig{});
  fusion.addLidarScan(measure(scene.wall, scene.wall_normals, FeatureShape::kPlanar, 0.0, 0), motionOfScan(0.0));
  fusion.addLidarScan(measure(scene.pole, scene.pole_dirs, FeatureShape::kLinear, 0.0, 100000), motionOfScan(0.0));
  const double t_camera = 0.08;
  const Eigen::Isometry3d T_world_camera = lidarPose(t_camera) * cameraFromLidar().inverse();
  const PinholeCamera cam = testCamera();
  const Eigen::Vector3d A_world(5.0, -1.0, 0.5), B_world(5.0, -1.0, 2.0);
  const ImageSegment seg{*cam.project(T_world_camera.inverse() * A_world), *cam.project(T_world_camera.inverse() * B_world)};
  const FusionResult r = fusion.process(t_camera, lidarPose(t_camera), {seg});
  ASSERT_EQ(r.lines.size(), 1u);
  EXPECT_EQ(r.lines[0].kind, FusionLineKind::kLinearCluster);
  EXPECT_LT((T_world_camera * r.lines[0].A - A_world).norm(), 0.01);
  EXPECT_LT((T_world_camera * r.lines[0].B - B_world).norm(), 0.01);
  ASSERT_EQ(r.lidar_updates.size(), 1u);
  EXPECT_GT(std::abs(r.lidar_updates[0].direction_world.z()), std::cos(0.5 * M_PI / 180.0));
  for (const auto id : r.lidar_updates[0].ids) EXPECT_GE(id, 100000u);  // pole points only
}

// The framework indexes only the features an image line can reach (within
// the neighbour angle of the cap round the optical axis that holds every
// segment's end rays); every segment, those ending in the image's corners
// included, must come out as with all features indexed: the same reject
// reason or the same line to the last bit. Returns the lines.
std::size_t expectTheLinesOfAllFeatures(const std::vector<TimedFeature>& features) {
  const PinholeCamera cam = testCamera();
  const Eigen::Isometry3d T_world_lidar = Eigen::Isometry3d::Identity();
  FusionFramework fusion(cam, cameraFromLidar(), FusionConfig{});
  fusion.addLidarScan(features, {0.0, T_world_lidar, 0.1, T_world_lidar});
  // Segments from each corner and edge midpoint to points across the image.
  const double r = cam.width() - 0.5, b = cam.height() - 0.5;
  const std::vector<Eigen::Vector2d> ends{{-0.5, -0.5}, {r, -0.5}, {-0.5, b}, {r, b}, {320.0, -0.5}, {-0.5, 240.0}};
  std::vector<ImageSegment> segments;
  for (const Eigen::Vector2d& a : ends)
    for (const Eigen::Vector2d& to : {Eigen::Vector2d(320.0, 240.0), Eigen::Vector2d(100.0, 400.0), Eigen::Vector2d(600.0, 60.0)})
      segments.push_back({a, to});
  const FusionResult result = fusion.process(0.05, T_world_lidar, segments);

  const std::vector<SphereFeature> all = fusion.featuresInCamera(T_world_lidar);
  const SphereIndex index(all);
  const LineReconstructor reconstructor(cam, FusionConfig{});
  decltype(FusionResult::rejected) rejected{};
  for (std::size_t i = 0; i < segments.size(); ++i) {
    RejectReason why = RejectReason::kNone;
    const auto line = reconstructor.reconstruct(segments[i], all, index, &why);
    if (!line) ++rejected[static_cast<std::size_t>(why)];
    const auto found = std::find_if(result.lines.begin(), result.lines.end(),
                                    [i](const FusionLine& l) { return l.segment_index == i; });
    EXPECT_EQ(line.has_value(), found != result.lines.end()) << "segment " << i << " reason " << int(why);
    if (!line || found == result.lines.end()) continue;
    EXPECT_EQ(line->A, found->A) << "segment " << i;
    EXPECT_EQ(line->B, found->B) << "segment " << i;
    EXPECT_EQ(line->neighbours, found->neighbours) << "segment " << i;
  }
  EXPECT_EQ(result.rejected, rejected);
  return result.lines.size();
}

TEST(FusionFramework, FeaturesOutsideTheViewChangeNoLine) {
  std::vector<TimedFeature> room;  // 10 x 10 x 4 m round a static LiDAR, walls sampled every 25 cm
  for (double a = -5.0; a <= 5.0; a += 0.25)
    for (double z = -1.5; z <= 2.5; z += 0.25) {
      const std::uint64_t id = room.size();
      room.push_back({{5.0, a, z}, Eigen::Vector3d::UnitX(), FeatureShape::kPlanar, 0.05, id});
      room.push_back({{-5.0, a, z}, Eigen::Vector3d::UnitX(), FeatureShape::kPlanar, 0.05, id + 1});
      room.push_back({{a, 5.0, z}, Eigen::Vector3d::UnitY(), FeatureShape::kPlanar, 0.05, id + 2});
      room.push_back({{a, -5.0, z}, Eigen::Vector3d::UnitY(), FeatureShape::kPlanar, 0.05, id + 3});
    }
  EXPECT_GE(expectTheLinesOfAllFeatures(room), 9u);
  // Only the wall behind the camera: nothing within reach of any segment.
  std::vector<TimedFeature> behind;
  for (const TimedFeature& f : room)
    if (f.p_lidar.x() < -4.9) behind.push_back(f);
  EXPECT_EQ(expectTheLinesOfAllFeatures(behind), 0u);

  // A pole 3 m away whose image runs from the centre through the top-left
  // corner, sampled every 10 cm so that the corner's nearest sample lies
  // just beyond the corner, outside the image's own cone.
  const PinholeCamera cam = testCamera();
  const Eigen::Isometry3d T_lidar_camera = cameraFromLidar().inverse();
  const Eigen::Vector3d centre = 3.0 * cam.unproject({320.0, 240.0}).normalized();
  const Eigen::Vector3d corner_ray = cam.unproject({-0.5, -0.5}).normalized();
  const Eigen::Vector3d along = (3.0 * corner_ray - centre).normalized();
  // Where the pole crosses the corner's ray: centre + s along = k corner_ray.
  const Eigen::Vector3d n = corner_ray.cross(along);
  const double s_corner = -corner_ray.cross(centre).dot(n) / n.squaredNorm();
  std::vector<TimedFeature> pole;
  for (double s = s_corner + 0.035 - 0.1 * 40; s <= s_corner + 0.2; s += 0.1)
    if (s >= 0.0)
      pole.push_back({T_lidar_camera * (centre + s * along), T_lidar_camera.linear() * along, FeatureShape::kLinear,
                      0.05, pole.size()});
  EXPECT_GE(expectTheLinesOfAllFeatures(pole), 1u);
}

TEST(FusionFramework, PointDepthsComeFromTheNearestSurface) {
  const Scene scene;
  FusionFramework fusion(testCamera(), cameraFromLidar(), FusionConfig{});
  fusion.addLidarScan(measure(scene.wall, scene.wall_normals, FeatureShape::kPlanar, 0.0, 0), motionOfScan(0.0));
  fusion.addLidarScan(measure(scene.pole, scene.pole_dirs, FeatureShape::kLinear, 0.0, 100000), motionOfScan(0.0));
  const double t = 0.1;
  const Eigen::Isometry3d T_camera_world = (lidarPose(t) * cameraFromLidar().inverse()).inverse();
  const PinholeCamera cam = testCamera();
  const Eigen::Vector3d on_wall = T_camera_world * Eigen::Vector3d(8.0, 2.0, 1.0);
  const Eigen::Vector3d on_pole = T_camera_world * Eigen::Vector3d(5.0, -1.0, 1.2);
  const auto depths = fusion.pointDepths(lidarPose(t), {*cam.project(on_wall), *cam.project(on_pole), {5.0, 5.0}}, 4.0);
  EXPECT_NEAR(depths[0], on_wall.z(), 0.05 * on_wall.z());
  EXPECT_NEAR(depths[1], on_pole.z(), 0.05);  // the pole, not the wall behind it
  EXPECT_TRUE(std::isnan(depths[2]));         // top-left corner: sky, nothing there
}

}  // namespace
}  // namespace lvslam::fusion
