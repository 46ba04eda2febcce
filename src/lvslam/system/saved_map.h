#pragma once
// The map one run saves for another (`lvslam run --map-out FILE`, read back
// by `--map-in FILE`): the loop closure's LiDAR keyframes at their final
// poses (each a registered scan's features: what place recognition and the
// ICP localise against, map_localizer.h) and the lines of lines.ply, all in
// the saving run's world frame, which is the map's frame. One binary file:
// the tag "LVSLAM-MAP\n", a format version, the payload's size and CRC-32,
// then the payload field by field (record_file.h's encoding, in the
// machine's byte order: little-endian on x86-64 and ARM). Reading checks the
// CRC and every field it can (feature class, flags, finite and bounded
// values, rotations), so a damaged or foreign file is an lvslam::Error
// naming it, not a wrong map.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lvslam/io/ply_writer.h"
#include "lvslam/loop/loop_closure.h"
#include "lvslam/loop/loop_keyframe.h"

namespace lvslam::system {

inline constexpr std::uint32_t kSavedMapVersion = 1;

struct SavedMap {
  std::vector<loop::LoopKeyframe> keyframes;  // T_odom_lidar: the keyframe's pose in the map's frame
  std::vector<PlySegment> lines;              // lines.ply's segments, same frame
};

// The map of a finished run: the loop closure's keyframes (odometry poses
// and features) at the poses its final graph gave them (`loop`, when it
// solved over the same keyframes), and the run's lines.
SavedMap savedMapOf(std::vector<loop::LoopKeyframe> keyframes, const std::optional<loop::LoopClosureResult>& loop,
                    std::vector<PlySegment> lines);

// Throws lvslam::Error naming the file when it cannot be written.
void writeSavedMap(const std::string& path, const SavedMap& map);
// Throws lvslam::Error naming the file and what is wrong with it.
SavedMap readSavedMap(const std::string& path);

}  // namespace lvslam::system
