// config/m2dgr.yaml against the facts of docs/m2dgr.md, and preset errors.
#include <gtest/gtest.h>

#include "lvslam/io/sensor_preset.h"
#include "support/temp_dir.h"

namespace lvslam {
namespace {

TEST(SensorPreset, M2dgrPresetHoldsTheDocumentedCalibration) {
  const SensorPreset p = loadSensorPreset(findSensorPreset("m2dgr"));
  EXPECT_EQ(p.lidar_topic, "/velodyne_points");
  EXPECT_EQ(p.camera_topic, "/camera/color/image_raw/compressed");
  ASSERT_TRUE(p.camera.has_value());
  EXPECT_EQ(p.camera->camera.width(), 640);
  EXPECT_EQ(p.camera->camera.height(), 480);
  EXPECT_EQ(p.camera->camera.fx(), 617.971050917033);
  EXPECT_EQ(p.camera->camera.cy(), 253.976983707814);
  EXPECT_EQ(p.camera->camera.distortion().k1, 0.148000794688248);
  EXPECT_EQ(p.lidar.rings, 32);
  // m2dgr.md gives T_lidar_camera = [R t]; the preset holds its inverse.
  Eigen::Matrix3d R;
  R << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  const Eigen::Isometry3d T_lidar_camera = p.T_camera_lidar.inverse();
  EXPECT_TRUE(T_lidar_camera.linear().isApprox(R, 1e-15));
  EXPECT_TRUE(T_lidar_camera.translation().isApprox(Eigen::Vector3d(0.30456, 0.00065, 0.65376), 1e-12));
  // The camera looks along the LiDAR's x: a point ahead of the robot is in front of the camera.
  EXPECT_GT((p.T_camera_lidar * Eigen::Vector3d(5, 0, 0)).z(), 0.0);
}

TEST(SensorPreset, ErrorsNameFileAndKey) {
  testing::TempDir dir;
  dir.write("bad.yaml", "format: lvslam-preset/1\ncamera:\n  width: 10\n  height: 10\n  intrinsics: [1, 1, 5]\n");
  const std::string message = testing::errorMessageOf([&] { loadSensorPreset(dir.file("bad.yaml")); });
  EXPECT_NE(message.find("bad.yaml"), std::string::npos) << message;
  EXPECT_NE(message.find("camera.intrinsics"), std::string::npos) << message;
  dir.write("noext.yaml", "format: lvslam-preset/1\ncamera:\n  width: 10\n  height: 10\n  intrinsics: [1, 1, 5, 5]\n");
  EXPECT_NE(testing::errorMessageOf([&] { loadSensorPreset(dir.file("noext.yaml")); }).find("'extrinsics'"),
            std::string::npos);
  dir.write("fmt.yaml", "format: lvslam-sequence/1\n");
  EXPECT_NE(testing::errorMessageOf([&] { loadSensorPreset(dir.file("fmt.yaml")); }).find("'format'"), std::string::npos);
  EXPECT_NE(testing::errorMessageOf([&] { findSensorPreset("no_such_preset"); }).find("no_such_preset"), std::string::npos);
}

// A typo in a preset would silently keep a default: it is an error naming the
// file and the key, at any depth.
TEST(SensorPreset, AnUnknownKeyIsAnErrorNamingFileAndKey) {
  testing::TempDir dir;
  dir.write("top.yaml", "format: lvslam-preset/1\nnmae: x\n");
  const std::string top = testing::errorMessageOf([&] { loadSensorPreset(dir.file("top.yaml")); });
  EXPECT_NE(top.find("top.yaml"), std::string::npos) << top;
  EXPECT_NE(top.find("nmae"), std::string::npos) << top;
  dir.write("deep.yaml", "format: lvslam-preset/1\nlidar:\n  rings: 32\n  rate: 10\n");
  const std::string deep = testing::errorMessageOf([&] { loadSensorPreset(dir.file("deep.yaml")); });
  EXPECT_NE(deep.find("rate"), std::string::npos) << deep;
  EXPECT_NE(deep.find("lidar"), std::string::npos) << deep;
  dir.write("topic.yaml", "format: lvslam-preset/1\ntopics:\n  imu: /imu\n");
  EXPECT_NE(testing::errorMessageOf([&] { loadSensorPreset(dir.file("topic.yaml")); }).find("imu"), std::string::npos);
}

}  // namespace
}  // namespace lvslam
