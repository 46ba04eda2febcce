#pragma once
// One ROS1 bag file (format 2.0) read through Debian's rosbag_storage: its
// topics, and the serialized messages of chosen topics in record order. A bag
// whose index is missing or damaged (cut off while recording or copying) is
// read record by record up to the damage instead; damage() says why (users
// such as BagSource warn with it).
// The ROS headers stay in the .cc (pimpl).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lvslam {

struct BagTopicInfo {
  std::string topic;
  std::string type;  // e.g. sensor_msgs/PointCloud2
  std::size_t messages = 0;
};

struct BagMessage {
  std::string topic;
  std::string type;
  double record_time = 0.0;         // when the recorder received it, seconds
  std::vector<std::uint8_t> data;   // the ROS1-serialized message
};

class RosbagReader {
 public:
  // Throws lvslam::Error naming the file when it is missing, not a bag, or
  // damaged before its first message.
  explicit RosbagReader(const std::string& path);
  ~RosbagReader();
  RosbagReader(const RosbagReader&) = delete;
  RosbagReader& operator=(const RosbagReader&) = delete;

  const std::string& path() const;
  std::vector<BagTopicInfo> topics() const;  // sorted by topic name
  std::optional<BagTopicInfo> topic(const std::string& name) const;
  // Time of the first and last message (record times); 0 for an empty bag.
  double beginTime() const;
  double endTime() const;
  // Why the file could only be read in part ("" for an intact bag).
  const std::string& damage() const;

  // Restricts next() to these topics (all when empty) and starts over.
  void select(const std::vector<std::string>& topics);
  // The next message of the selected topics in record order; none at the end.
  std::optional<BagMessage> next();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lvslam
