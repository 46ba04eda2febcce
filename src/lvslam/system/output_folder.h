#pragma once
// `lvslam run`'s --out folder, made ready before the run: a folder that
// cannot be made or written is named now, not after the whole run (whose
// results would then be lost), and a reused folder must not show an earlier
// run's files as this run's (a subsystems/visual_map_3.tum of a run with
// three maps would stay beside a later run's two; a run without result would
// leave the old trajectory.tum).
#include <string>

namespace lvslam::system {

// Creates `out_dir` if needed and removes the files `lvslam run` writes
// (trajectory.tum, stats.json, ..., subsystems/visual_map_<n>.tum,
// subsystems/lidar_camera.tum); anything else there stays. Throws
// lvslam::Error naming the folder or file when it cannot.
void prepareOutputFolder(const std::string& out_dir);

}  // namespace lvslam::system
