#include "output_publisher.h"

#include <cmath>
#include <cstring>

#include <fmt/format.h>

#include "lvslam/core/se3.h"

namespace lvslam::ros_node {

namespace {

using system::OutputSource;

KeyValue keyValue(const std::string& key, const std::string& value) {
  KeyValue kv;
  kv.key = key.c_str();
  kv.value = value.c_str();
  return kv;
}

// Twist of the child frame in the child frame, from two poses dt apart.
void setTwist(Odometry& odom, const Eigen::Isometry3d& T_prev, const Eigen::Isometry3d& T_cur, double dt) {
  const Eigen::Isometry3d step = T_prev.inverse() * T_cur;
  const Eigen::Vector3d v = T_cur.rotation().transpose() * (T_cur.translation() - T_prev.translation()) / dt;
  const Eigen::AngleAxisd turn(step.rotation());
  const Eigen::Vector3d w = turn.axis() * turn.angle() / dt;
  odom.twist.twist.linear.x = v.x();
  odom.twist.twist.linear.y = v.y();
  odom.twist.twist.linear.z = v.z();
  odom.twist.twist.angular.x = w.x();
  odom.twist.twist.angular.y = w.y();
  odom.twist.twist.angular.z = w.z();
}

// Whether the pose moved far enough from the path's last one to join it.
bool pathStep(const Path& path, const Eigen::Isometry3d& T_world_child) {
  if (path.poses.empty()) return true;
  const auto& last = path.poses.back().pose;
  const Eigen::Vector3d p(last.position.x, last.position.y, last.position.z);
  const Eigen::Quaterniond q(last.orientation.w, last.orientation.x, last.orientation.y, last.orientation.z);
  constexpr double kStepM = 0.1, kTurnRad = 5.0 * M_PI / 180.0;
  return (T_world_child.translation() - p).norm() >= kStepM ||
         q.angularDistance(Eigen::Quaterniond(T_world_child.rotation())) >= kTurnRad;
}

Point toPoint(const Eigen::Vector3d& p) {
  Point out;
  out.x = p.x();
  out.y = p.y();
  out.z = p.z();
  return out;
}

}  // namespace

OutputPublisher::OutputPublisher(ros::NodeHandle& nh, const NodeParams& params)
    : params_(params),
      parent_frame_(params.odom_frame.empty() ? params.world_frame : params.odom_frame),
      child_frame_(params.base_frame.empty() ? params.camera_frame : params.base_frame) {
  ros::NodeHandle root;
  odometry_ = nh.advertise<Odometry>("odometry", 100);
  tf_ = root.advertise<TFMessage>("/tf", 100);
  tf_static_ = root.advertise<TFMessage>("/tf_static", 1, true);
  path_ = nh.advertise<Path>("path", 1, true);
  map_ = nh.advertise<PointCloud2>("map", 1, true);
  lines_ = nh.advertise<MarkerArray>("lines", 1, true);
  diagnostics_ = root.advertise<DiagnosticArray>("/diagnostics", 10);
  path_msg_.header.frame_id = params.world_frame.c_str();
  // The rig's fixed transforms, once: rviz then shows the raw sweeps too.
  TFMessage fixed;
  fixed.transforms.push_back(toTransform(params.preset.T_camera_lidar, 0.0, params.camera_frame, params.lidar_frame));
  if (!params.base_frame.empty())
    fixed.transforms.push_back(toTransform(params.T_camera_base.inverse(), 0.0, params.base_frame, params.camera_frame));
  if (!params.odom_frame.empty())
    fixed.transforms.push_back(toTransform(Eigen::Isometry3d::Identity(), 0.0, params.world_frame, params.odom_frame));
  tf_static_.publish(fixed);
}

Eigen::Isometry3d OutputPublisher::outputPose(const Eigen::Isometry3d& T_world_camera) const {
  return params_.base_frame.empty() ? T_world_camera : T_world_camera * params_.T_camera_base;
}

void OutputPublisher::publishFrame(const system::FrameOutput& frame) {
  std::unique_lock lock(mutex_);
  ++state_.frames;
  state_.t = frame.t;
  if (!frame.T_world_camera) {
    ++state_.without_pose;
    return;
  }
  const bool switched = state_.source && *state_.source != frame.source;
  state_.switches += switched;
  state_.source = frame.source;
  state_.problem = frame.problem;
  state_.fused = frame.fused;
  const Eigen::Isometry3d T_world_child = outputPose(*frame.T_world_camera);

  Odometry odom;
  odom.header.stamp = toRosTime(frame.t);
  odom.header.frame_id = parent_frame_.c_str();
  odom.child_frame_id = child_frame_.c_str();
  odom.pose.pose = toPose(T_world_child);
  // The estimator's covariance (fused mode; other modes leave it all zero,
  // unknown), carried to the child frame: t_child = t_camera + R_camera t_camera_child.
  if (frame.covariance) {
    const Eigen::Vector3d lever =
        params_.base_frame.empty() ? Eigen::Vector3d::Zero() : Eigen::Vector3d(params_.T_camera_base.translation());
    Matrix6d J = Matrix6d::Identity();
    J.block<3, 3>(0, 3) = -skew(frame.T_world_camera->linear() * lever);
    const Matrix6d covariance = J * *frame.covariance * J.transpose();
    for (int i = 0; i < 6; ++i)
      for (int k = 0; k < 6; ++k) odom.pose.covariance[static_cast<std::size_t>(6 * i + k)] = covariance(i, k);
  }
  if (last_pose_ && frame.t > last_pose_->first)
    setTwist(odom, last_pose_->second, T_world_child, frame.t - last_pose_->first);
  last_pose_ = {frame.t, T_world_child};

  if (pathStep(path_msg_, T_world_child)) {
    PoseStamped stamped;
    stamped.header = odom.header;
    stamped.header.frame_id = params_.world_frame.c_str();  // the same pose: world -> odom is the identity
    stamped.pose = odom.pose.pose;
    path_msg_.poses.push_back(stamped);
    path_changed_ = true;
  }

  TFMessage tf;
  tf.transforms.push_back(toTransform(T_world_child, frame.t, parent_frame_, child_frame_));
  const DetectionState state = state_;
  const std::map<std::string, std::size_t> counts = last_counts_;
  lock.unlock();
  odometry_.publish(odom);
  tf_.publish(tf);
  if (switched) publishState(state, counts);  // each switch at once
}

void OutputPublisher::publishPath() {
  std::unique_lock lock(mutex_);
  if (!path_changed_) return;
  path_changed_ = false;
  path_msg_.header.stamp = path_msg_.poses.back().header.stamp;
  const Path path = path_msg_;
  lock.unlock();
  path_.publish(path);
}

void OutputPublisher::publishDiagnostics(const std::map<std::string, std::size_t>& counts) {
  std::unique_lock lock(mutex_);
  last_counts_ = counts;
  const DetectionState state = state_;
  lock.unlock();
  publishState(state, counts);
}

void OutputPublisher::publishState(const DetectionState& state, const std::map<std::string, std::size_t>& counts) {
  DiagnosticStatus status;
  status.name = "lvslam: detection module";
  status.hardware_id = "lvslam_node";
  std::string message;
  if (!state.source) {
    status.level = DiagnosticStatus::WARN;
    message = state.frames == 0 ? "waiting for data" : "no pose yet";
  } else if (*state.source == OutputSource::kVisual) {
    status.level = DiagnosticStatus::OK;
    message = state.fused ? "vision and LiDAR fused" : "vision";
  } else {
    status.level = state.problem.empty() ? DiagnosticStatus::OK : DiagnosticStatus::WARN;
    message = state.problem.empty() ? "LiDAR" : "LiDAR only: " + state.problem;
  }
  status.message = message.c_str();
  status.values.push_back(keyValue("time", fmt::format("{:.6f}", state.t)));
  status.values.push_back(keyValue("frames", std::to_string(state.frames)));
  status.values.push_back(keyValue("frames without pose", std::to_string(state.without_pose)));
  status.values.push_back(keyValue("switches", std::to_string(state.switches)));
  status.values.push_back(keyValue("vision problem", state.problem));
  for (const auto& [kind, n] : counts) status.values.push_back(keyValue("dropped: " + kind, std::to_string(n)));
  DiagnosticArray array;
  array.header.stamp = toRosTime(state.t);
  array.status.push_back(status);
  diagnostics_.publish(array);
}

void OutputPublisher::publishMap(const std::vector<Eigen::Vector3f>& points_world) {
  PointCloud2 cloud;
  {
    std::lock_guard lock(mutex_);
    cloud.header.stamp = toRosTime(state_.t);
  }
  cloud.header.frame_id = params_.world_frame.c_str();
  cloud.height = 1;
  cloud.width = static_cast<std::uint32_t>(points_world.size());
  for (std::uint32_t i = 0; i < 3; ++i) {
    PointField f;
    f.name = std::string(1, static_cast<char>('x' + i)).c_str();
    f.offset = 4 * i;
    f.datatype = PointField::FLOAT32;
    f.count = 1;
    cloud.fields.push_back(f);
  }
  cloud.point_step = 12;
  cloud.row_step = 12 * cloud.width;
  cloud.is_dense = true;
  cloud.data.resize(cloud.row_step);
  for (std::size_t i = 0; i < points_world.size(); ++i) std::memcpy(cloud.data.data() + 12 * i, points_world[i].data(), 12);
  map_.publish(cloud);
}

void OutputPublisher::publishLines(const std::vector<PlySegment>& lines_world) {
  Marker marker;
  marker.header.frame_id = params_.world_frame.c_str();
  {
    std::lock_guard lock(mutex_);
    marker.header.stamp = toRosTime(state_.t);
  }
  marker.ns = "lvslam_lines";
  marker.id = 0;
  marker.type = Marker::LINE_LIST;
  marker.action = Marker::ADD;
  marker.pose.orientation.w = 1.0;
  marker.scale.x = 0.02;
  for (const PlySegment& s : lines_world) {
    marker.points.push_back(toPoint(s.a));
    marker.points.push_back(toPoint(s.b));
    for (int k = 0; k < 2; ++k) {
      std_msgs::ColorRGBA_<Allocator<void>> c;
      c.r = s.r / 255.0f;
      c.g = s.g / 255.0f;
      c.b = s.b_colour / 255.0f;
      c.a = 1.0f;
      marker.colors.push_back(c);
    }
  }
  MarkerArray array;
  array.markers.push_back(marker);
  lines_.publish(array);
}

}  // namespace lvslam::ros_node
