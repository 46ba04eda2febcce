#pragma once
// LiDAR scan files: little-endian float32 records whose fields are named by
// `point_fields` (docs/sequence-format.md). Unknown field names are skipped.
#include <string>
#include <vector>

#include "lvslam/core/lidar_scan.h"

namespace lvslam {

// Where each known field sits in a record (-1 when absent).
struct ScanLayout {
  int x = -1, y = -1, z = -1, intensity = -1, time = -1, ring = -1;
  int fields = 0;
  static ScanLayout fromFields(const std::vector<std::string>& point_fields);
  std::size_t recordBytes() const { return static_cast<std::size_t>(fields) * sizeof(float); }
};

struct ScanReadStats {
  std::size_t records = 0;
  std::size_t dropped = 0;  // non-finite coordinates or time, or at the origin
};

// Reads the points of one file into `scan` (timestamp left as is). Throws
// lvslam::Error naming the file when it is missing or its size is not a
// multiple of the record size.
ScanReadStats readScanFile(const std::string& path, const ScanLayout& layout, LidarScan& scan);

// Writes scan points in the given field order (fields it does not know are 0).
void writeScanFile(const std::string& path, const std::vector<std::string>& point_fields,
                   const LidarScan& scan);

}  // namespace lvslam
