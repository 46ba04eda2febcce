#pragma once
// `lvslam convert to-bag`: a sequence folder as a ROS1 bag, so that any
// sequence (a simulated one with its exact ground truth, a converted KITTI
// drive) can be replayed into lvslam_node with `rosbag play`. Scans become
// sensor_msgs/PointCloud2 (x y z intensity ring time, the Velodyne driver's
// layout, time relative to the header stamp), images sensor_msgs/Image (mono8
// or bgr8) or, as image_transport's compressed topic, CompressedImage (PNG,
// lossless; JPEG, as most robots record). Each message is recorded when a live driver would publish it:
// an image at its stamp, a sweep at its last point. Beside the bag goes a
// sensor preset (config/m2dgr.yaml's schema) with the sequence's camera,
// extrinsics and the bag's topics: the node's `preset` parameter.
#include <string>

namespace lvslam {

enum class BagImageFormat { kRaw, kPng, kJpeg };

struct SequenceToBagOptions {
  std::string sequence_dir;
  std::string bag_path;      // written; the preset goes to <bag without .bag>.preset.yaml
  std::string lidar_topic = "/velodyne_points";
  std::string camera_topic;  // "" for /camera/image_raw, or /camera/image_raw/compressed when compressed
  BagImageFormat image_format = BagImageFormat::kRaw;
  std::string lidar_frame = "velodyne", camera_frame = "camera";
};

struct SequenceToBagStats {
  std::size_t images = 0, scans = 0, points = 0;
  std::string preset_path;
};

// Throws lvslam::Error naming the sequence file or the bag at fault.
SequenceToBagStats writeSequenceBag(const SequenceToBagOptions& options);

// The camera topic the bag gets for `options` (its own, or the default).
std::string cameraTopicOf(const SequenceToBagOptions& options);

// Where writeSequenceBag puts the preset of `bag_path`.
std::string presetPathForBag(const std::string& bag_path);

}  // namespace lvslam
