#pragma once
// KITTI raw time stamps: text like "2011-09-26 13:02:25.964389445" (UTC),
// one a line in timestamps.txt files.
#include <optional>
#include <string>
#include <vector>

namespace lvslam {

// Seconds since the Unix epoch; none when the text is not such a time stamp.
std::optional<double> parseKittiTimestamp(const std::string& text);

// Throws lvslam::Error("file:line", ...) on a malformed line.
std::vector<double> readKittiTimestamps(const std::string& path);

}  // namespace lvslam
