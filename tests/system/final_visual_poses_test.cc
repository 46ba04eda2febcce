#include "lvslam/system/final_visual_poses.h"

#include <gtest/gtest.h>

#include "lvslam/core/se3.h"
#include "support/record_files.h"

namespace lvslam::system {
namespace {

Eigen::Isometry3d pose(double a, double b) {
  return expSE3((Vector6d() << a, -b, 0.5 * a, 0.1 * b, -0.2 * a, 0.3 * b).finished());
}

int addKeyframe(visual::VisualMap& map, const Eigen::Isometry3d& T_camera_world) {
  visual::Keyframe kf;
  kf.T_camera_world = T_camera_world;
  return map.addKeyframe(std::move(kf));
}

VisualFrameRecord trackedFrame(int map_id, int keyframe, const Eigen::Isometry3d& T_keyframe_camera,
                               const Eigen::Isometry3d& T_world_camera_then) {
  VisualFrameRecord v;
  v.result.pose_valid = true;
  v.result.map_id = map_id;
  v.result.replay.reference_keyframe = keyframe;
  v.result.replay.T_keyframe_camera = T_keyframe_camera;
  v.result.T_world_camera = T_world_camera_then;
  return v;
}

// Local BA moves keyframes after the frames were tracked; the frames follow
// their keyframes, culled ones through their parents, in whichever map they
// were tracked.
TEST(PlaceOnFinalKeyframes, FramesFollowTheirKeyframesFinalPoses) {
  std::vector<visual::VisualMap> retired(1);
  const int a = addKeyframe(retired[0], pose(0.1, 0.2));
  visual::VisualMap current;
  const int b = addKeyframe(current, pose(1.0, 0.5));
  const int c = addKeyframe(current, pose(1.2, 0.4));
  const Eigen::Isometry3d T_a_cam = pose(0.05, 0.01), T_c_cam = pose(0.02, -0.03);

  std::vector<VisualFrameRecord> frames;
  frames.push_back(trackedFrame(0, a, T_a_cam, pose(9, 9)));
  frames.back().result.initial_reference = StampedPose{1.0, pose(8, 8)};
  frames.back().result.initial_reference_keyframe = a;
  frames.push_back(trackedFrame(1, c, T_c_cam, pose(9, 9)));
  frames.push_back(trackedFrame(1, b, T_c_cam, pose(9, 9)));
  frames.back().result.pose_valid = false;  // lost: nothing to place
  frames.push_back(trackedFrame(1, -1, T_c_cam, pose(9, 9)));  // no keyframe
  frames.push_back(trackedFrame(2, b, T_c_cam, pose(9, 9)));   // no such map

  // After tracking: a moves; c is culled (its parent is b, the older one) and b moves.
  retired[0].keyframe(a).T_camera_world = pose(0.12, 0.25);
  const Eigen::Isometry3d T_b_c = current.keyframe(b).T_camera_world * current.keyframe(c).T_camera_world.inverse();
  current.removeKeyframe(c);
  current.keyframe(b).T_camera_world = pose(1.1, 0.45);

  RecordFile<VisualFrameRecord> file = testing::recordFileOf(frames);
  placeOnFinalKeyframes(retired, current, file);
  frames = testing::vectorOf(file);
  ASSERT_TRUE(frames[0].T_world_camera_final);
  EXPECT_TRUE(frames[0].T_world_camera_final->isApprox(pose(0.12, 0.25).inverse() * T_a_cam, 1e-12));
  ASSERT_TRUE(frames[0].initial_reference_final);
  EXPECT_TRUE(frames[0].initial_reference_final->isApprox(pose(0.12, 0.25).inverse(), 1e-12));
  ASSERT_TRUE(frames[1].T_world_camera_final);
  const Eigen::Isometry3d T_world_c = (T_b_c.inverse() * pose(1.1, 0.45)).inverse();
  EXPECT_TRUE(frames[1].T_world_camera_final->isApprox(T_world_c * T_c_cam, 1e-12));
  EXPECT_FALSE(frames[2].T_world_camera_final);
  EXPECT_FALSE(frames[3].T_world_camera_final);
  EXPECT_FALSE(frames[4].T_world_camera_final);
  EXPECT_FALSE(frames[1].initial_reference_final);
}

}  // namespace
}  // namespace lvslam::system
