#pragma once
// sensor_msgs/PointCloud2 to LidarScan. Fields are found by name and
// datatype, never by position: x, y, z (required), intensity, ring (or
// laser_id), and a per-point time as `time`, `t`, `timestamp` or split
// `time_sec` + `time_nsec`, relative to the header stamp or absolute.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lvslam/core/lidar_scan.h"
#include "lvslam/io/sequence_info.h"

namespace lvslam {

struct DecodedScan {
  // timestamp: the header stamp; points[i].time relative to it (seconds).
  LidarScan scan;
  // Whether the stamp is the start (point times >= 0) or the end (<= 0) of the
  // sweep; none when the points carry no time. A stamp inside the sweep is
  // moved to the sweep's first point (kStart) and `restamped` is set.
  std::optional<TimeReference> time_reference;
  bool restamped = false;
  std::size_t total_points = 0;    // width * height
  std::size_t invalid_points = 0;  // dropped: non-finite or zero x/y/z, non-finite time
  std::string frame_id;
};

// Decodes a ROS1-serialized sensor_msgs/PointCloud2 (any of the 8 PointField
// datatypes, either byte order, any point_step / row_step). Throws
// lvslam::Error(where, ...) naming the field on a missing x/y/z, a field that
// does not fit in a point, or data shorter than the layout; `where` names the
// bag and topic.
DecodedScan decodePointCloud2(const std::vector<std::uint8_t>& serialized, const std::string& where);

// Moves a scan's timestamp to the first (kStart) or last (kEnd) point time of
// its sweep and shifts the point times to match: the same absolute times.
void restampScan(LidarScan& scan, TimeReference reference);

}  // namespace lvslam
