#include "node_params.h"

#include <vector>

#include <fmt/format.h>

#include "lvslam/core/error.h"

namespace lvslam::ros_node {

namespace {

std::string where(const ros::NodeHandle& nh, const std::string& name) { return "parameter " + nh.resolveName(name); }

template <class T>
T get(const ros::NodeHandle& nh, const std::string& name, const T& fallback) {
  T value = fallback;
  if (nh.hasParam(name) && !nh.getParam(name, value))
    throw Error(where(nh, name), "has the wrong type");
  return value;
}

Eigen::Isometry3d transformParam(const ros::NodeHandle& nh, const std::string& name) {
  std::vector<double> m;
  if (!nh.getParam(name, m) || m.size() != 16)
    throw Error(where(nh, name), "must be a list of 16 numbers (row-major 4x4)");
  Eigen::Matrix4d M;
  for (int i = 0; i < 16; ++i) M(i / 4, i % 4) = m[static_cast<std::size_t>(i)];
  const Eigen::Matrix3d R = M.topLeftCorner<3, 3>();
  if (!(R.transpose() * R).isApprox(Eigen::Matrix3d::Identity(), 1e-3) || R.determinant() < 0.0)
    throw Error(where(nh, name), "rotation part is not a rotation");
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::Quaterniond(R).normalized().toRotationMatrix();
  T.translation() = M.topRightCorner<3, 1>();
  return T;
}

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

NodeParams loadNodeParams(const ros::NodeHandle& nh) {
  NodeParams p;
  const std::string preset = get<std::string>(nh, "preset", "m2dgr");
  p.preset = loadSensorPreset(findSensorPreset(preset));
  p.lidar_topic = get<std::string>(nh, "lidar_topic", p.preset.lidar_topic);
  p.camera_topic = get<std::string>(nh, "camera_topic", p.preset.camera_topic);
  if (p.lidar_topic.empty() && p.camera_topic.empty())
    throw Error(where(nh, "preset"), fmt::format("preset '{}' names no topic; set ~lidar_topic or ~camera_topic", preset));
  if (!p.camera_topic.empty() && !p.preset.camera)
    throw Error(where(nh, "preset"), fmt::format("preset '{}' has no camera block for topic {}", preset, p.camera_topic));
  p.camera_compressed = get<bool>(nh, "camera_compressed", endsWith(p.camera_topic, "/compressed"));
  p.mode = get<std::string>(nh, "mode", p.mode);
  if (p.mode != "fused" && p.mode != "lidar" && p.mode != "visual")
    throw Error(where(nh, "mode"), "must be fused, lidar or visual, not '" + p.mode + "'");
  p.config_path = get<std::string>(nh, "config", "");
  p.deterministic = get<bool>(nh, "deterministic", false);
  p.out_dir = get<std::string>(nh, "out", "");
  p.groundtruth_path = get<std::string>(nh, "groundtruth", "");
  const int queue = get<int>(nh, "queue_size", static_cast<int>(p.queue_size));
  if (queue < 1) throw Error(where(nh, "queue_size"), "must be at least 1");
  p.queue_size = static_cast<std::size_t>(queue);
  p.max_wait_s = get<double>(nh, "max_wait", p.max_wait_s);
  if (!(p.max_wait_s > 0.0)) throw Error(where(nh, "max_wait"), "must be positive (seconds)");
  p.world_frame = get<std::string>(nh, "world_frame", p.world_frame);
  p.camera_frame = get<std::string>(nh, "camera_frame", p.camera_frame);
  p.lidar_frame = get<std::string>(nh, "lidar_frame", p.lidar_frame);
  p.base_frame = get<std::string>(nh, "base_frame", "");
  if (!p.base_frame.empty()) p.T_camera_base = transformParam(nh, "T_camera_base");
  p.odom_frame = get<std::string>(nh, "odom_frame", "");
  for (const std::string& frame : {p.camera_frame, p.lidar_frame, p.base_frame})
    if (!p.odom_frame.empty() && (p.odom_frame == p.world_frame || p.odom_frame == frame))
      throw Error(where(nh, "odom_frame"), "'" + p.odom_frame + "' must differ from world_frame, camera_frame, lidar_frame and base_frame");
  p.map_period_s = get<double>(nh, "map_period", p.map_period_s);
  p.map_voxel_m = get<double>(nh, "map_voxel", p.map_voxel_m);
  p.path_period_s = get<double>(nh, "path_period", p.path_period_s);
  if (!(p.map_period_s > 0.0) || !(p.map_voxel_m > 0.0) || !(p.path_period_s > 0.0))
    throw Error(where(nh, "map_period"), "map_period, map_voxel and path_period must be positive");
  return p;
}

}  // namespace lvslam::ros_node
