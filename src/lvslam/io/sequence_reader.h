#pragma once
// Streams a sequence folder: camera images and LiDAR scans merged in time
// order, one file loaded at a time (never the whole sequence in memory).
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "lvslam/core/image_frame.h"
#include "lvslam/core/lidar_scan.h"
#include "lvslam/core/trajectory.h"
#include "lvslam/io/scan_file.h"
#include "lvslam/io/sensor_source.h"
#include "lvslam/io/sequence_info.h"
#include "lvslam/io/times_file.h"

namespace lvslam {

class SequenceReader : public SensorSource {
 public:
  // Reads sequence.yaml and the times files; throws lvslam::Error naming
  // the file and key or line on anything malformed.
  explicit SequenceReader(const std::string& directory);

  const SequenceInfo& info() const { return info_; }
  const std::string& directory() const { return directory_; }
  const std::vector<TimedFile>& cameraFiles() const { return camera_files_; }
  const std::vector<TimedFile>& lidarFiles() const { return lidar_files_; }
  bool hasGroundTruth() const;
  Trajectory groundTruth() const;  // throws when there is none

  // The next image or scan in time order (a scan before an image at the same
  // time stamp); none at the end.
  std::optional<SensorData> next() override;
  Calibration calibration() const override;
  // A sensor counts when sequence.yaml declares it and its times.txt lists data.
  bool hasCamera() const override { return info_.camera.has_value() && !camera_files_.empty(); }
  bool hasLidar() const override { return info_.lidar.has_value() && !lidar_files_.empty(); }
  void rewind() { next_camera_ = next_lidar_ = 0; }

  ImageFrame loadImage(std::size_t index) const;
  LidarScan loadScan(std::size_t index) const;

 private:
  std::string directory_;
  SequenceInfo info_;
  std::vector<TimedFile> camera_files_;
  std::vector<TimedFile> lidar_files_;
  std::optional<ScanLayout> layout_;
  // Values that read but lose quality (point_fields, intrinsics), said once
  // the first file has been read.
  std::vector<std::string> plausibility_warnings_;
  std::size_t next_camera_ = 0, next_lidar_ = 0;
};

}  // namespace lvslam
