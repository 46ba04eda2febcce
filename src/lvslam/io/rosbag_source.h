#pragma once
// A SensorSource over ROS1 bags: the images and scans of the chosen topics of
// one recording (one or several bag files, read in time order), merged by
// header stamp. Calibration comes from the options (e.g. a sensor preset).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lvslam/io/sensor_source.h"
#include "lvslam/io/sequence_info.h"

namespace lvslam {

struct BagSourceOptions {
  std::string lidar_topic;   // sensor_msgs/PointCloud2; "" for none
  std::string camera_topic;  // sensor_msgs/Image or CompressedImage; "" for none
  Calibration calibration;
  LidarInfo lidar;           // rings and rate_hz, informative
};

class BagSource : public SensorSource {
 public:
  // Opens the files, orders them by their first message, and checks that each
  // topic exists (in one file at least) with a supported type. Throws
  // lvslam::Error naming the bag and topic otherwise.
  BagSource(const std::vector<std::string>& files, const BagSourceOptions& options);
  ~BagSource() override;

  // Throws lvslam::Error naming bag, topic and field on a malformed message.
  // Messages whose stamp does not increase on their topic are skipped (warned).
  // The two topics' clocks are checked against each other as the messages
  // arrive: each stamp against its record time (the recorder's clock, the
  // same for both); when one topic's stamps move by more than kMaxClockStep
  // against it and the other's do not, that sensor's clock jumped and
  // next() throws lvslam::Error naming the bag, the topic, the stamp and the
  // size of the jump (a drop-out moves stamps and record times together).
  std::optional<SensorData> next() override;
  static constexpr double kMaxClockStep = 1.0;  // s: far above transport delay jitter
  Calibration calibration() const override { return options_.calibration; }
  bool hasCamera() const override { return !options_.camera_topic.empty(); }
  bool hasLidar() const override { return !options_.lidar_topic.empty(); }

  // The LiDAR as the first scan shows it: point_fields (x, y, z and what the
  // cloud has of intensity, time, ring) and whether header stamps are the
  // start or the end of the sweep (later scans are restamped to match).
  LidarInfo lidarInfo() const;
  const std::vector<std::string>& files() const { return files_; }  // in time order
  std::size_t skippedMessages() const;

 private:
  class TopicStream;
  void checkClocks();
  BagSourceOptions options_;
  std::vector<std::string> files_;
  std::unique_ptr<TopicStream> lidar_, camera_;
  std::optional<double> clock_difference_;  // LiDAR minus camera stamp-to-record offset, as last seen
};

std::unique_ptr<SensorSource> openBagSource(const std::vector<std::string>& files, const BagSourceOptions& options);

}  // namespace lvslam
