#include "lvslam/io/sensor_preset.h"

#include <filesystem>
#include <map>

#include <fmt/format.h>

#include "lvslam/core/config_dir.h"
#include "lvslam/core/error.h"
#include "lvslam/core/yaml_config.h"

namespace lvslam {

const std::vector<std::string>& presetKeys(const std::string& block) {
  static const std::map<std::string, std::vector<std::string>> keys{
      {"", {"format", "name", "topics", "camera", "lidar", "extrinsics", "groundtruth"}},
      {"topics", {"lidar", "camera"}},
      {"camera", {"model", "width", "height", "intrinsics", "distortion", "rate_hz"}},
      {"camera.distortion", {"model", "coeffs"}},
      {"lidar", {"rings", "rate_hz"}},
      {"extrinsics", {"T_camera_lidar"}},
      {"groundtruth", {"frame"}}};
  return keys.at(block);
}

namespace {

void requireKnownPresetKeys(const YamlConfig& root) {
  root.requireKnownKeys(presetKeys(""));
  for (const char* block : {"topics", "camera", "lidar", "extrinsics", "groundtruth"})
    if (const auto node = root.find(block)) node->requireKnownKeys(presetKeys(block));
  if (const auto camera = root.find("camera"))
    if (const auto distortion = camera->find("distortion")) distortion->requireKnownKeys(presetKeys("camera.distortion"));
}

}  // namespace

Calibration SensorPreset::calibration() const { return calibrationOf(camera, T_camera_lidar); }

SensorPreset loadSensorPreset(const std::string& path) {
  const YamlConfig root = YamlConfig::loadFile(path);
  requireFormat(root, kSensorPresetFormat);
  requireKnownPresetKeys(root);
  SensorPreset preset;
  preset.name = root.getString("name", std::filesystem::path(path).stem().string());
  if (const auto topics = root.find("topics")) {
    preset.lidar_topic = topics->getString("lidar", "");
    preset.camera_topic = topics->getString("camera", "");
  }
  if (const auto camera = root.find("camera")) preset.camera = parseCameraInfo(*camera);
  if (const auto lidar = root.find("lidar")) {
    preset.lidar.rings = lidar->getInt("rings", 0);
    preset.lidar.rate_hz = lidar->getDouble("rate_hz", 0.0);
    if (preset.lidar.rings < 0) lidar->at("rings").fail("must not be negative");
  }
  if (const auto ext = root.find("extrinsics")) {
    preset.T_camera_lidar = parseTransformMatrix(ext->at("T_camera_lidar"));
  } else if (preset.camera) {
    root.at("extrinsics");  // throws: a camera needs its pose relative to the LiDAR
  }
  if (const auto gt = root.find("groundtruth")) preset.groundtruth_frame = parseGroundTruthFrame(gt->at("frame"));
  return preset;
}

std::string findSensorPreset(const std::string& name_or_path) {
  if (std::filesystem::is_regular_file(name_or_path)) return name_or_path;
  const std::filesystem::path in_config = std::filesystem::path(configDir()) / (name_or_path + ".yaml");
  if (std::filesystem::is_regular_file(in_config)) return in_config.string();
  throw Error(name_or_path, fmt::format("no such preset file, nor a preset '{}' in {}", name_or_path, configDir()));
}

}  // namespace lvslam
