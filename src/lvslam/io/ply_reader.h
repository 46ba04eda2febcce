#pragma once
// Reads back the PLY files ply_writer.h writes (map.ply: binary vertices with
// float x, y, z, intensity; lines.ply: ASCII vertex pairs joined by coloured
// edges), for the HTML report of an existing run folder.
#include <string>
#include <vector>

#include "lvslam/io/ply_writer.h"

namespace lvslam {

// Throws lvslam::Error naming the file when it is not such a PLY or is
// truncated.
std::vector<PlyPoint> readPointCloudPly(const std::string& path);
std::vector<PlySegment> readLineSegmentsPly(const std::string& path);

}  // namespace lvslam
