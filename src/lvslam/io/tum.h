#pragma once
// TUM trajectory text files: "timestamp tx ty tz qx qy qz qw" per line, '#'
// comments, giving T_world_frame. Also KITTI pose files (12 numbers a line).
#include <fstream>
#include <string>

#include "lvslam/core/trajectory.h"

namespace lvslam {

// Throws lvslam::Error("file:line", why) on a malformed line, a quaternion of
// zero norm, or time stamps that do not increase.
Trajectory readTum(const std::string& path);
void writeTum(const std::string& path, const Trajectory& trajectory);

// A TUM file written pose by pose as they are made, each line flushed: a run
// stopped by a fault or killed leaves the poses made so far, in the format
// writeTum writes.
class TumStream {
 public:
  explicit TumStream(const std::string& path);  // throws lvslam::Error naming it when it cannot be written
  void add(const StampedPose& pose);

 private:
  std::string path_;
  std::ofstream out_;
};

// KITTI odometry poses: a row-major 3x4 [R|t] per line; times from a file
// with one time stamp a line (same count), or 0, 1, 2, ... when times_path is empty.
Trajectory readKittiPoses(const std::string& path, const std::string& times_path = "");

}  // namespace lvslam
