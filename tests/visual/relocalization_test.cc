// Relocalisation pose guesses: the motion model carried over the lost frames
// first, then the last pose, then the reference keyframe.
#include "lvslam/visual/tracking/relocalization.h"

#include <gtest/gtest.h>

namespace lvslam::visual {
namespace {

Eigen::Isometry3d pose(double x, double yaw) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(x, 0.1, 0.2);
  return T;
}

TEST(Relocalization, GuessesCarryTheMotionOverTheLostFramesThenFallBack) {
  VisualMap map;
  Keyframe k;
  k.T_camera_world = pose(5.0, 0.3);
  const int reference = map.addKeyframe(k);
  const Eigen::Isometry3d T_last = pose(1.0, 0.0);
  const Eigen::Isometry3d velocity = pose(0.1, 0.01);
  const std::vector<Eigen::Isometry3d> guesses = relocalizationGuesses(map, T_last, velocity, 2, reference, 4);
  ASSERT_EQ(guesses.size(), 3u);  // no covisible neighbours in this map
  const Eigen::Isometry3d expected = velocity * velocity * velocity * T_last;  // lost 2 frames: this is the 3rd
  EXPECT_TRUE(guesses[0].isApprox(expected, 1e-12));
  EXPECT_TRUE(guesses[1].isApprox(T_last, 1e-12));
  EXPECT_TRUE(guesses[2].isApprox(k.T_camera_world, 1e-12));
  EXPECT_EQ(relocalizationGuesses(map, T_last, velocity, 0, reference + 7, 4).size(), 2u);  // unknown reference
}

}  // namespace
}  // namespace lvslam::visual
