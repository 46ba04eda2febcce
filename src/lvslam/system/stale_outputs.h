#pragma once
// A reused --out folder must not show an earlier run's files as this run's:
// a subsystems/visual_map_3.tum of a run with three maps stayed beside a
// later run's two, and a run without result left the old trajectory.tum.
#include <string>

namespace lvslam::system {

// Removes the files `lvslam run` writes (trajectory.tum, stats.json, ...,
// subsystems/visual_map_<n>.tum, subsystems/lidar_camera.tum) from
// `out_dir`; anything else there stays. Throws lvslam::Error naming a file
// that cannot be removed.
void removeRunOutputs(const std::string& out_dir);

}  // namespace lvslam::system
