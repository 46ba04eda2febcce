#pragma once
// The ROS1 message types lvslam_node uses, instantiated with io/'s
// rosmsg::Allocator (the generated templates need the allocator rebind that
// C++20 removed from std::allocator), and conversions to and from lvslam's
// types. Only ros/ includes this.
#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/io/rosbag_msgs.h"

#include <diagnostic_msgs/DiagnosticArray.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <tf2_msgs/TFMessage.h>
#include <visualization_msgs/MarkerArray.h>

namespace lvslam::ros_node {

using rosmsg::Allocator;
using rosmsg::CompressedImage;
using rosmsg::Image;
using rosmsg::PointCloud2;
using rosmsg::PointField;
using Odometry = nav_msgs::Odometry_<Allocator<void>>;
using Path = nav_msgs::Path_<Allocator<void>>;
using PoseStamped = geometry_msgs::PoseStamped_<Allocator<void>>;
using Pose = geometry_msgs::Pose_<Allocator<void>>;
using TransformStamped = geometry_msgs::TransformStamped_<Allocator<void>>;
using TFMessage = tf2_msgs::TFMessage_<Allocator<void>>;
using Marker = visualization_msgs::Marker_<Allocator<void>>;
using MarkerArray = visualization_msgs::MarkerArray_<Allocator<void>>;
using Point = geometry_msgs::Point_<Allocator<void>>;
using DiagnosticArray = diagnostic_msgs::DiagnosticArray_<Allocator<void>>;
using DiagnosticStatus = diagnostic_msgs::DiagnosticStatus_<Allocator<void>>;
using KeyValue = diagnostic_msgs::KeyValue_<Allocator<void>>;

inline ros::Time toRosTime(double t) {
  ros::Time stamp;
  stamp.fromSec(t);
  return stamp;
}

inline Pose toPose(const Eigen::Isometry3d& T) {
  Pose pose;
  const Eigen::Quaterniond q(T.rotation());
  pose.position.x = T.translation().x();
  pose.position.y = T.translation().y();
  pose.position.z = T.translation().z();
  pose.orientation.x = q.x();
  pose.orientation.y = q.y();
  pose.orientation.z = q.z();
  pose.orientation.w = q.w();
  return pose;
}

inline TransformStamped toTransform(const Eigen::Isometry3d& T_parent_child, double t, const std::string& parent,
                                    const std::string& child) {
  TransformStamped tf;
  tf.header.stamp = toRosTime(t);
  tf.header.frame_id = parent.c_str();
  tf.child_frame_id = child.c_str();
  const Pose pose = toPose(T_parent_child);
  tf.transform.translation.x = pose.position.x;
  tf.transform.translation.y = pose.position.y;
  tf.transform.translation.z = pose.position.z;
  tf.transform.rotation = pose.orientation;
  return tf;
}

// A received message back to its ROS1 bytes, for io/'s decoders (which the
// bag reader shares): one copy, small beside the decoding.
template <class Message>
std::vector<std::uint8_t> serialize(const Message& msg) {
  std::vector<std::uint8_t> bytes(ros::serialization::serializationLength(msg));
  ros::serialization::OStream stream(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  ros::serialization::serialize(stream, msg);
  return bytes;
}

}  // namespace lvslam::ros_node
