#include "lvslam/system/final_visual_poses.h"

namespace lvslam::system {

namespace {

const visual::VisualMap* mapWithId(const std::vector<visual::VisualMap>& retired, const visual::VisualMap& current,
                                   int map_id) {
  if (map_id < 0 || static_cast<std::size_t>(map_id) > retired.size()) return nullptr;
  return static_cast<std::size_t>(map_id) == retired.size() ? &current : &retired[static_cast<std::size_t>(map_id)];
}

}  // namespace

void placeOnFinalKeyframes(const std::vector<visual::VisualMap>& retired, const visual::VisualMap& current,
                           RecordFile<VisualFrameRecord>& frames) {
  frames.update([&](VisualFrameRecord& frame) {
    const visual::VisualFrameResult& r = frame.result;
    if (!r.pose_valid) return;
    const visual::VisualMap* map = mapWithId(retired, current, r.map_id);
    if (map == nullptr) return;
    if (r.replay.reference_keyframe >= 0)
      if (const auto T_keyframe_world = map->keyframePose(r.replay.reference_keyframe))
        frame.T_world_camera_final = T_keyframe_world->inverse() * r.replay.T_keyframe_camera;
    if (r.initial_reference && r.initial_reference_keyframe >= 0)
      if (const auto T_first_world = map->keyframePose(r.initial_reference_keyframe))
        frame.initial_reference_final = T_first_world->inverse();
  });
}

void relocateInFinalMaps(const visual::VisualSlam& slam, RecordFile<VisualFrameRecord>& frames) {
  frames.update([&slam](VisualFrameRecord& frame) {
    if (frame.T_world_camera_final)
      if (const auto T = slam.relocateInFinalMap(frame.result, *frame.T_world_camera_final))
        frame.T_world_camera_final = *T;
  });
}

Eigen::Isometry3d visualPoseOf(const VisualFrameRecord& v, bool final_poses) {
  return final_poses && v.T_world_camera_final ? *v.T_world_camera_final : v.result.T_world_camera;
}

StampedPose initialReferenceOf(const VisualFrameRecord& v, bool final_poses) {
  StampedPose first = *v.result.initial_reference;
  if (final_poses && v.initial_reference_final) first.T_world_frame = *v.initial_reference_final;
  return first;
}

}  // namespace lvslam::system
