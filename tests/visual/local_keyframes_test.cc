// Nearby keyframes (map reuse): which keyframes join the local map by place
// and view direction, on keyframes at exact poses.
#include "lvslam/visual/tracking/local_keyframes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lvslam::visual {
namespace {

// T_camera_world of a camera at `centre` whose optical axis is rotated by
// `yaw_deg` about the world y axis (z forward, y down).
Eigen::Isometry3d cameraAt(const Eigen::Vector3d& centre, double yaw_deg) {
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  T_world_camera.linear() = Eigen::AngleAxisd(yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitY()).toRotationMatrix();
  T_world_camera.translation() = centre;
  return T_world_camera.inverse();
}

class NearbyKeyframesTest : public ::testing::Test {
 protected:
  int add(const Eigen::Vector3d& centre, double yaw_deg) {
    Keyframe k;
    k.T_camera_world = cameraAt(centre, yaw_deg);
    return map_.addKeyframe(std::move(k));
  }
  VisualMap map_;
  LocalKeyframeConfig config_ = [] {
    LocalKeyframeConfig c;
    c.nearby_min_age = 0;
    return c;
  }();
};

TEST_F(NearbyKeyframesTest, ClosestFirstWithinRadiusAndViewAngle) {
  const int far = add({3.0, 0, 0}, 0);
  const int near = add({0.2, 0, 0}, 10);
  const int nearer = add({0, 0, 0.1}, -20);
  const int facing_away = add({0.1, 0, 0}, 90);  // 90 deg > 35 deg
  const int edge = add({0, 0, 0.9}, 34);
  const std::vector<int> got = nearbyKeyframes(map_, cameraAt({0, 0, 0}, 0), 1.0, {}, config_);
  EXPECT_EQ(got, (std::vector<int>{nearer, near, edge}));
  (void)far;
  (void)facing_away;
}

TEST_F(NearbyKeyframesTest, ExcludedCappedAndOff) {
  std::vector<int> ids;
  for (int i = 0; i < 8; ++i) ids.push_back(add({0.1 * i, 0, 0}, 0));
  config_.nearby_max = 3;
  EXPECT_EQ(nearbyKeyframes(map_, cameraAt({0, 0, 0}, 0), 1.0, {ids[0], ids[2]}, config_),
            (std::vector<int>{ids[1], ids[3], ids[4]}));
  EXPECT_TRUE(nearbyKeyframes(map_, cameraAt({0, 0, 0}, 0), 0.0, {}, config_).empty());  // radius 0: off
  config_.nearby_max = 0;
  EXPECT_TRUE(nearbyKeyframes(map_, cameraAt({0, 0, 0}, 0), 1.0, {}, config_).empty());
}

TEST_F(NearbyKeyframesTest, TheNewestAreLeftToTheCovisibilityGraph) {
  std::vector<int> ids;
  for (int i = 0; i < 5; ++i) ids.push_back(add({0.1 * i, 0, 0}, 0));
  config_.nearby_min_age = 3;  // only the two oldest qualify
  EXPECT_EQ(nearbyKeyframes(map_, cameraAt({0.4, 0, 0}, 0), 1.0, {}, config_), (std::vector<int>{ids[1], ids[0]}));
  map_.removeKeyframe(ids[0]);  // age counts the keyframes kept
  EXPECT_EQ(nearbyKeyframes(map_, cameraAt({0.4, 0, 0}, 0), 1.0, {}, config_), (std::vector<int>{ids[1]}));
  config_.nearby_min_age = 10;
  EXPECT_TRUE(nearbyKeyframes(map_, cameraAt({0, 0, 0}, 0), 1.0, {}, config_).empty());
}

}  // namespace
}  // namespace lvslam::visual
