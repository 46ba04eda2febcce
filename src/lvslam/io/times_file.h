#pragma once
// camera/times.txt and lidar/times.txt: "<timestamp> <file>" per line.
#include <string>
#include <vector>

namespace lvslam {

struct TimedFile {
  double t = 0.0;
  std::string path;  // resolved against the folder of times.txt
  int line = 0;      // in times.txt, for messages
};

// Throws lvslam::Error("times.txt:line", why) on a malformed line, a time
// stamp that does not increase, or a file that does not exist.
std::vector<TimedFile> readTimesFile(const std::string& path);

// The median time between consecutive frames (0 with fewer than two).
double medianPeriod(const std::vector<TimedFile>& files);

// Gaps longer than `factor` times the median period: sensor drop-outs or
// clock jumps. Returns the indices i where t[i] - t[i-1] is such a gap.
std::vector<std::size_t> findTimeJumps(const std::vector<TimedFile>& files, double factor = 5.0);

}  // namespace lvslam
