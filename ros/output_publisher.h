#pragma once
// What lvslam_node publishes, from the online output as each frame is made:
//   ~odometry   nav_msgs/Odometry of the online pose (T_world_camera, or
//               T_world_base with ~base_frame), twist from the last two poses
//   /tf         world_frame -> camera_frame (or base_frame); with
//               ~odom_frame, odom_frame -> camera_frame (or base_frame)
//   /tf_static  camera_frame -> lidar_frame (T_camera_lidar),
//               base_frame -> camera_frame when there is a base, and
//               world_frame -> odom_frame (identity) with ~odom_frame (latched)
//   ~path       nav_msgs/Path of the online poses, one per 10 cm or 5 deg of
//               motion (an hour's path stays small), every ~path_period
//   ~map        the live LiDAR map, PointCloud2 (every ~map_period; latched)
//   ~lines      fusion lines and visual line landmarks, MarkerArray (latched;
//               on shutdown, when the system hands its line map over)
//   /diagnostics the detection module's state, each switch at once, and the
//               input's drop counts
// Stamps are the data's: the output follows the sensor clock, not the wall.
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <ros/ros.h>

#include "node_params.h"
#include "ros_messages.h"
#include "lvslam/io/ply_writer.h"
#include "lvslam/system/online/online_output.h"

namespace lvslam::ros_node {

class OutputPublisher {
 public:
  OutputPublisher(ros::NodeHandle& private_nh, const NodeParams& params);

  void publishFrame(const system::FrameOutput& frame);  // any thread
  void publishPath();
  // `counts`: drops and input problems by kind, for the diagnostics.
  void publishDiagnostics(const std::map<std::string, std::size_t>& counts);
  void publishMap(const std::vector<Eigen::Vector3f>& points_world);
  void publishLines(const std::vector<PlySegment>& lines_world);

 private:
  struct DetectionState {
    std::size_t frames = 0, switches = 0, without_pose = 0;
    std::optional<system::OutputSource> source;
    std::string problem;
    bool fused = false;
    double t = 0.0;
  };
  Eigen::Isometry3d outputPose(const Eigen::Isometry3d& T_world_camera) const;  // camera or base
  void publishState(const DetectionState& state, const std::map<std::string, std::size_t>& counts);

  const NodeParams& params_;
  std::string parent_frame_, child_frame_;  // of the published pose
  ros::Publisher odometry_, tf_, tf_static_, path_, map_, lines_, diagnostics_;
  std::mutex mutex_;
  Path path_msg_;
  bool path_changed_ = false;
  std::optional<std::pair<double, Eigen::Isometry3d>> last_pose_;
  DetectionState state_;
  std::map<std::string, std::size_t> last_counts_;
};

}  // namespace lvslam::ros_node
