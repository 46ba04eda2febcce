#pragma once
// The node's sensor input: subscribes to the PointCloud2 and the Image or
// CompressedImage topic, decodes each message with io/'s decoders (the bag
// reader's own), checks it against the preset, and pushes it into the live
// source. Bad input (an empty cloud, a cloud without per-point time, an
// image encoding it cannot read, an image whose size is not the
// calibration's) and dropped input (out of order, late, queue overflow) are
// counted per kind and logged once per kind; nothing of it stops the node.
#include <functional>
#include <optional>

#include <ros/ros.h>

#include "input_problems.h"
#include "node_params.h"
#include "ros_messages.h"
#include "lvslam/io/live_source.h"
#include "lvslam/io/sequence_info.h"

namespace lvslam::ros_node {

class TopicInput {
 public:
  struct Hooks {
    std::function<void(double stamp)> image_arrived;  // before decoding: the latency counts from here
    std::function<void(const LidarScan&)> scan_accepted;
  };
  TopicInput(ros::NodeHandle& nh, const NodeParams& params, LiveSensorSource& source, InputProblems& problems,
             Hooks hooks);
  void shutdown();  // no more callbacks after it returns

 private:
  void onCloud(const boost::shared_ptr<const PointCloud2>& msg);
  void onImage(const boost::shared_ptr<const Image>& msg);
  void onCompressedImage(const boost::shared_ptr<const CompressedImage>& msg);
  void acceptImage(ImageFrame frame, const std::string& where);
  void push(SensorData data, const std::string& where);

  const NodeParams& params_;
  LiveSensorSource& source_;
  InputProblems& problems_;
  Hooks hooks_;
  std::optional<TimeReference> time_reference_;  // of the first scan; later scans are restamped to it
  ros::Subscriber lidar_sub_, camera_sub_;
};

}  // namespace lvslam::ros_node
