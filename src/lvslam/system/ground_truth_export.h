#pragma once
// groundtruth.tum of a run folder: the recording's ground truth in the frame
// trajectory.tum is written in (the camera's, or the LiDAR's in mode lidar),
// so the report, or evo, compares like with like from the folder alone.
#include <optional>

#include "lvslam/io/recording.h"
#include "lvslam/system/output_assembly.h"

namespace lvslam::system {

// None when the recording has no ground truth.
std::optional<Trajectory> groundTruthInOutputFrame(const Recording& recording, const SystemOutput& output);

}  // namespace lvslam::system
