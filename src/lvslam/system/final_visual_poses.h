#pragma once
// The visual frames placed on their maps' keyframes as these stand at the end
// of the run, as ORB-SLAM's SaveTrajectoryTUM places them: local BA and the
// map correction go on moving a keyframe for many frames after it was made,
// with observations that came later, while a frame's pose relative to the
// keyframe it was tracked against is what tracking measured. A culled
// keyframe is found through its parent (VisualMap::keyframePose).
#include <vector>

#include "lvslam/system/frame_records.h"
#include "lvslam/system/record_fields.h"
#include "lvslam/system/record_file.h"
#include "lvslam/visual/data/visual_map.h"
#include "lvslam/visual/visual_slam.h"

namespace lvslam::system {

// Sets T_world_camera_final (and initial_reference_final) of every frame with
// a pose whose keyframe its map knows. Map id i < retired.size() is
// retired[i], id retired.size() the current map (VisualSlam's numbering).
void placeOnFinalKeyframes(const std::vector<visual::VisualMap>& retired, const visual::VisualMap& current,
                           RecordFile<VisualFrameRecord>& frames);

// Then each placed frame that is not a keyframe is optimised again, from its
// placed pose, on the observations it was tracked with, against its map's
// landmarks as they stand at the end (VisualSlam::relocateInFinalMap): local
// BA went on moving those landmarks after the frame was tracked. A frame too
// few of whose landmarks remain keeps its placed pose.
void relocateInFinalMaps(const visual::VisualSlam& slam, RecordFile<VisualFrameRecord>& frames);

// A frame's visual pose in its map: on the final keyframes when asked and
// known, else as tracked; and likewise the map's first view (a frame with
// result.initial_reference only).
Eigen::Isometry3d visualPoseOf(const VisualFrameRecord& v, bool final_poses);
StampedPose initialReferenceOf(const VisualFrameRecord& v, bool final_poses);

}  // namespace lvslam::system
