#pragma once
// The LiDAR map as the report's 3D view shows it: a 10-minute run's map has
// millions of points, more than a browser orbits fluidly, so the view gets
// at most `budget` of them, one per voxel of an edge that keeps under the
// budget (from 5 cm, grown by the square root of the count's excess each try).
#include <cstddef>
#include <vector>

#include "lvslam/io/ply_writer.h"

namespace lvslam::report {

struct DecimatedMap {
  std::vector<PlyPoint> points;  // the first point of each voxel, in map order
  double voxel_m = 0.0;          // 0: every point kept
};

DecimatedMap decimateMap(const std::vector<PlyPoint>& points, std::size_t budget);

}  // namespace lvslam::report
