#pragma once
// A sensor preset (config/<name>.yaml): which topics of a recording carry the
// camera and the LiDAR, and the calibration and LiDAR facts of the rig, for
// `lvslam convert bag --preset` and `lvslam run --bag --preset`. The schema is
// documented at the top of config/m2dgr.yaml.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/core/calibration.h"
#include "lvslam/io/sequence_info.h"

namespace lvslam {

inline constexpr const char* kSensorPresetFormat = "lvslam-preset/1";

struct SensorPreset {
  std::string name;
  std::string lidar_topic;   // "" when the preset names none
  std::string camera_topic;
  std::optional<CameraInfo> camera;
  LidarInfo lidar;           // rings and rate_hz (point_fields and time_reference are the converter's)
  Eigen::Isometry3d T_camera_lidar = Eigen::Isometry3d::Identity();
  std::optional<GroundTruthFrame> groundtruth_frame;

  Calibration calibration() const;
};

// The schema's keys of one block: "" (the top level), "topics", "camera",
// "camera.distortion", "lidar", "extrinsics" or "groundtruth". A preset is
// ours, not a recording's: the loader refuses any other key (a typo would
// silently keep a default) and `convert to-bag` writes only these.
const std::vector<std::string>& presetKeys(const std::string& block);

// Parses and validates; throws lvslam::Error(file, "key '...': why"), also
// for a key the schema does not have.
SensorPreset loadSensorPreset(const std::string& path);

// A preset file path, or the name of one in the project's config/ folder
// ("m2dgr" -> <config>/m2dgr.yaml). Throws lvslam::Error when neither exists.
std::string findSensorPreset(const std::string& name_or_path);

}  // namespace lvslam
