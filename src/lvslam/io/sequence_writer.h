#pragma once
// Writes a sequence folder incrementally (times.txt lines are appended as
// frames arrive), so a long simulation or conversion never holds it all.
#include <fstream>
#include <string>

#include <opencv2/core.hpp>

#include "lvslam/core/lidar_scan.h"
#include "lvslam/core/trajectory.h"
#include "lvslam/io/sequence_info.h"

namespace lvslam {

class SequenceWriter {
 public:
  // Creates the folder (and camera/, lidar/ as the info asks) and writes
  // sequence.yaml. Throws lvslam::Error when the folder cannot be written.
  SequenceWriter(const std::string& directory, const SequenceInfo& info);

  // Time stamps must increase per sensor; images are 8-bit gray or BGR.
  void writeImage(double t, const cv::Mat& image);
  void writeScan(const LidarScan& scan);
  // groundtruth.txt (TUM); info.groundtruth_frame must be set.
  void writeGroundTruth(const Trajectory& trajectory);

  const std::string& directory() const { return directory_; }

 private:
  std::string directory_;
  SequenceInfo info_;
  std::ofstream camera_times_, lidar_times_;
  std::size_t camera_count_ = 0, lidar_count_ = 0;
  double last_camera_t_ = 0.0, last_lidar_t_ = 0.0;
};

}  // namespace lvslam
