#pragma once
// The pieces of the report's data, as JSON the page reads: trajectories
// (optionally moved into the ground truth's world), their error series,
// the decimated LiDAR map and the line map.
#include <limits>
#include <string>
#include <vector>

#include "lvslam/core/trajectory.h"
#include "lvslam/eval/umeyama.h"
#include "lvslam/io/ply_writer.h"
#include "lvslam/report/map_decimation.h"
#include "lvslam/report/trajectory_errors.h"

namespace lvslam::report {

// {"name", "t": [...], "p": [x,y,z,...], "q": [qx,qy,qz,qw,...]}, as in the
// file (the page moves it into the ground truth's world for the plots);
// every k-th pose when there are more than max_poses (a ground truth at
// 200 Hz over ten minutes is 120 000 poses, more than a plot can show).
std::string trajectoryJson(const std::string& name, const Trajectory& trajectory,
                           std::size_t max_poses = std::numeric_limits<std::size_t>::max());

// The most ground-truth poses a page carries for display (its errors use them all).
inline constexpr std::size_t kGroundTruthDisplayPoses = 20000;

// {"alignment", "scale", "R": [row-major 3x3], "t": [3] (T_gt_est),
//  "series": [{"name", "unit", "t", "v", "stats": {...}}]}
std::string errorsJson(const TrajectoryErrors& errors);

// {"points_total", "voxel_m", "p": [...], "cls": [...]} (cls = PLY intensity)
std::string mapJson(const DecimatedMap& map, std::size_t points_total);

// {"p": [ax,ay,az,bx,by,bz,...], "rgb": [r,g,b,...]}
std::string linesJson(const std::vector<PlySegment>& segments);

}  // namespace lvslam::report
