#pragma once
// lvslam_node's parameters (private namespace, ~name), read once at start.
// Topics, camera and T_camera_lidar come from the same sensor presets as
// `lvslam run --bag --preset` (config/m2dgr.yaml); the topics may be
// overridden here.
#include <optional>
#include <string>

#include <Eigen/Geometry>
#include <ros/node_handle.h>

#include "lvslam/io/sensor_preset.h"

namespace lvslam::ros_node {

struct NodeParams {
  SensorPreset preset;
  std::string lidar_topic, camera_topic;
  bool camera_compressed = false;  // sensor_msgs/CompressedImage (a topic ending in /compressed)
  std::string mode = "fused";      // fused, lidar or visual, as `lvslam run --mode`
  std::string config_path;         // SystemConfig YAML, defaults otherwise
  bool deterministic = false;      // one thread in a fixed order, as `lvslam run --deterministic`
  std::string out_dir;             // written on shutdown as `lvslam run --out` does; "" for none
  std::string groundtruth_path;    // optional TUM ground truth: accuracy printed on shutdown
  std::size_t queue_size = 64;     // sensor items held before the oldest is dropped
  double max_wait_s = 1.0;         // message time an item waits for a silent sensor
  std::string world_frame = "map", camera_frame = "camera";
  std::string lidar_frame = "velodyne";  // static TF camera_frame -> lidar_frame (the preset's T_camera_lidar)
  // Optional robot base: TF and odometry then give world -> base_frame
  // through the static T_camera_base (row-major 4x4).
  std::string base_frame;
  // Optional REP-105 odometry frame: the pose then goes out as odom_frame ->
  // camera (or base), with world_frame -> odom_frame the identity on
  // /tf_static (the online pose never jumps: it is the odometry; loop
  // corrections are offline only), as LIO-SAM publishes map -> odom.
  std::string odom_frame;
  Eigen::Isometry3d T_camera_base = Eigen::Isometry3d::Identity();
  double map_period_s = 2.0;       // the LiDAR map is published this often (wall clock)
  double map_voxel_m = 0.2;
  double path_period_s = 0.5;
};

// Throws lvslam::Error naming the parameter and why.
NodeParams loadNodeParams(const ros::NodeHandle& private_nh);

}  // namespace lvslam::ros_node
