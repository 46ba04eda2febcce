#pragma once
// `lvslam convert bag`: ROS1 bags of one recording to a sequence folder.
#include <optional>
#include <string>
#include <vector>

#include "lvslam/io/rosbag_reader.h"
#include "lvslam/io/sensor_preset.h"
#include "lvslam/io/sequence_info.h"

namespace lvslam {

struct BagConvertOptions {
  std::vector<std::string> bags;               // one recording, any order
  std::string lidar_topic, camera_topic;       // override the preset's topics
  std::optional<SensorPreset> preset;          // camera, extrinsics, LiDAR facts
  std::string groundtruth_path;                // TUM file, optional
  std::optional<GroundTruthFrame> groundtruth_frame;  // overrides the preset's
  std::string out_dir;
  std::string name;                            // sequence name (default: the folder name)
};

struct BagConvertStats {
  std::size_t images = 0;
  std::size_t scans = 0;
  std::size_t points = 0;
  std::size_t skipped = 0;      // messages whose stamp did not increase
  std::size_t groundtruth = 0;  // poses
  LidarInfo lidar;
};

// Throws lvslam::Error naming the bag, topic and field on bad input.
BagConvertStats convertBags(const BagConvertOptions& options);

}  // namespace lvslam
