#pragma once
// sequence.yaml of the sequence folder, version 1 (docs/sequence-format.md).
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/core/calibration.h"
#include "lvslam/core/camera.h"

namespace lvslam {

inline constexpr const char* kSequenceFormat = "lvslam-sequence/1";

enum class TimeReference { kStart, kEnd };
enum class GroundTruthFrame { kCamera, kLidar };

struct CameraInfo {
  PinholeCamera camera;
  double rate_hz = 0.0;  // nominal, informative (0 when absent)
};

struct LidarInfo {
  int rings = 0;         // informative (0 when absent)
  double rate_hz = 0.0;  // nominal, informative (0 when absent)
  std::vector<std::string> point_fields{"x", "y", "z", "intensity", "time", "ring"};
  TimeReference time_reference = TimeReference::kStart;
};

struct SequenceInfo {
  std::string name;
  std::optional<CameraInfo> camera;
  std::optional<LidarInfo> lidar;
  Eigen::Isometry3d T_camera_lidar = Eigen::Isometry3d::Identity();
  std::optional<GroundTruthFrame> groundtruth_frame;

  Calibration calibration() const;
};

class YamlConfig;

// The `camera` block and a row-major 4x4 pose (rotation within 1e-3, snapped
// to the closest rotation) of sequence.yaml; also used by sensor presets.
CameraInfo parseCameraInfo(const YamlConfig& node);
Eigen::Isometry3d parseTransformMatrix(const YamlConfig& node);
// Throws lvslam::Error naming the file and key unless root's `format` is `expected`.
void requireFormat(const YamlConfig& root, const char* expected);
// The `groundtruth.frame` value ("camera" or "lidar").
GroundTruthFrame parseGroundTruthFrame(const YamlConfig& frame);
// The camera model (when there is a camera) and the extrinsic.
Calibration calibrationOf(const std::optional<CameraInfo>& camera, const Eigen::Isometry3d& T_camera_lidar);

// Parses and validates; throws lvslam::Error(file, "key '...': why").
SequenceInfo readSequenceInfo(const std::string& yaml_path);
void writeSequenceInfo(const std::string& yaml_path, const SequenceInfo& info);

}  // namespace lvslam
