#pragma once
// Opens what a user points lvslam at, a sequence folder or ROS1 bags with a
// sensor preset, as one SensorSource plus its ground truth when there is one.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lvslam/core/trajectory.h"
#include "lvslam/io/sensor_source.h"
#include "lvslam/io/sequence_info.h"

namespace lvslam {

struct RecordingRequest {
  std::string sequence_dir;            // a sequence folder, or
  std::vector<std::string> bag_files;  // ROS1 bags of one recording, with
  std::string preset;                  // a preset name (config/<name>.yaml) or file
  std::string lidar_topic, camera_topic;  // override the preset's topics
  std::string groundtruth_file;        // TUM ground truth for bags (frame from the preset)
};

struct Recording {
  std::string name;
  std::unique_ptr<SensorSource> source;
  std::optional<Trajectory> ground_truth;
  GroundTruthFrame ground_truth_frame = GroundTruthFrame::kCamera;
  std::string ground_truth_path;
};

// Throws lvslam::Error naming the file, key or option at fault.
Recording openRecording(const RecordingRequest& request);

}  // namespace lvslam
