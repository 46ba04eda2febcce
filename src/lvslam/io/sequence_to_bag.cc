#include "lvslam/io/sequence_to_bag.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <opencv2/imgcodecs.hpp>
#include <yaml-cpp/yaml.h>

#include "lvslam/core/error.h"
#include "lvslam/io/recording.h"
#include "lvslam/io/rosbag_msgs.h"
#include "lvslam/io/sensor_preset.h"

#include <rosbag/bag.h>

namespace lvslam {

namespace {

namespace fs = std::filesystem;

ros::Time rosTime(double t) {
  ros::Time stamp;
  stamp.fromSec(t);
  return stamp;
}

rosmsg::PointField field(const char* name, std::uint32_t offset, std::uint8_t datatype) {
  rosmsg::PointField f;
  f.name = name;
  f.offset = offset;
  f.datatype = datatype;
  f.count = 1;
  return f;
}

// The Velodyne driver's point layout: x y z (pad) intensity ring time, 32 bytes.
constexpr std::uint32_t kPointStep = 32;
constexpr std::uint8_t kUint16 = 4, kFloat32 = 7;

rosmsg::PointCloud2 toCloud(const LidarScan& scan, const std::string& frame) {
  rosmsg::PointCloud2 cloud;
  cloud.header.stamp = rosTime(scan.timestamp);
  cloud.header.frame_id = frame.c_str();
  cloud.height = 1;
  cloud.width = static_cast<std::uint32_t>(scan.size());
  cloud.fields = {field("x", 0, kFloat32), field("y", 4, kFloat32), field("z", 8, kFloat32),
                  field("intensity", 16, kFloat32), field("ring", 20, kUint16), field("time", 24, kFloat32)};
  cloud.point_step = kPointStep;
  cloud.row_step = kPointStep * cloud.width;
  cloud.is_dense = true;
  cloud.data.assign(cloud.row_step, 0);
  for (std::size_t i = 0; i < scan.size(); ++i) {
    const LidarPoint& p = scan.points[i];
    std::uint8_t* out = cloud.data.data() + kPointStep * i;
    std::memcpy(out, p.p.data(), 12);
    std::memcpy(out + 16, &p.intensity, 4);
    std::memcpy(out + 20, &p.ring, 2);
    std::memcpy(out + 24, &p.time, 4);
  }
  return cloud;
}

rosmsg::Image toImage(const ImageFrame& frame, const std::string& camera_frame) {
  const cv::Mat& image = frame.image;
  rosmsg::Image msg;
  msg.header.stamp = rosTime(frame.timestamp);
  msg.header.frame_id = camera_frame.c_str();
  msg.height = static_cast<std::uint32_t>(image.rows);
  msg.width = static_cast<std::uint32_t>(image.cols);
  msg.encoding = image.channels() == 1 ? "mono8" : "bgr8";
  msg.step = static_cast<std::uint32_t>(image.cols * image.elemSize());
  msg.data.resize(static_cast<std::size_t>(msg.step) * image.rows);
  for (int r = 0; r < image.rows; ++r) std::memcpy(msg.data.data() + r * msg.step, image.ptr(r), msg.step);
  return msg;
}

// As image_transport's compressed plugin writes it: "<encoding>; <codec> compressed <encoding>".
rosmsg::CompressedImage toCompressed(const ImageFrame& frame, const std::string& camera_frame, BagImageFormat format) {
  const bool png = format == BagImageFormat::kPng;
  std::vector<std::uint8_t> bytes;
  const std::vector<int> params = png ? std::vector<int>{} : std::vector<int>{cv::IMWRITE_JPEG_QUALITY, 95};
  if (!cv::imencode(png ? ".png" : ".jpg", frame.image, bytes, params))
    throw Error(camera_frame, "cannot compress the image at " + std::to_string(frame.timestamp));
  rosmsg::CompressedImage msg;
  msg.header.stamp = rosTime(frame.timestamp);
  msg.header.frame_id = camera_frame.c_str();
  const std::string encoding = frame.image.channels() == 1 ? "mono8" : "bgr8";
  msg.format = (encoding + "; " + (png ? "png" : "jpeg") + " compressed " + encoding).c_str();
  msg.data.assign(bytes.begin(), bytes.end());
  return msg;
}

// A live driver publishes a sweep once its last point is measured.
double publishTime(const LidarScan& scan) {
  float last = 0.0f;
  for (const LidarPoint& p : scan.points) last = std::max(last, p.time);
  return scan.timestamp + static_cast<double>(last);
}

// The sequence's own sequence.yaml blocks under the preset schema's keys.
void writePreset(const SequenceToBagOptions& options, const std::string& path) {
  const std::string yaml_path = (fs::path(options.sequence_dir) / "sequence.yaml").string();
  const YAML::Node sequence = YAML::LoadFile(yaml_path);
  YAML::Node preset;
  preset["format"] = kSensorPresetFormat;
  preset["name"] = sequence["name"] ? sequence["name"].as<std::string>() : fs::path(options.sequence_dir).filename().string();
  preset["topics"]["lidar"] = options.lidar_topic;
  preset["topics"]["camera"] = cameraTopicOf(options);
  // Only the preset schema's keys: a sequence may carry others (ignored there, refused in a preset).
  for (const char* block : {"camera", "lidar", "extrinsics", "groundtruth"}) {
    const YAML::Node from = sequence[block];
    if (!from || !from.IsMap()) continue;
    for (const std::string& key : presetKeys(block))
      if (from[key]) preset[block][key] = from[key];
  }
  std::ofstream out(path);
  out << "# Sensor preset of the bag beside it, written by `lvslam convert to-bag` from " << yaml_path << "\n"
      << preset << "\n";
  if (!out) throw Error(path, "cannot write the preset");
}

}  // namespace

std::string cameraTopicOf(const SequenceToBagOptions& options) {
  if (!options.camera_topic.empty()) return options.camera_topic;
  return options.image_format == BagImageFormat::kRaw ? "/camera/image_raw" : "/camera/image_raw/compressed";
}

std::string presetPathForBag(const std::string& bag_path) {
  fs::path p(bag_path);
  if (p.extension() == ".bag") p.replace_extension();
  return p.string() + ".preset.yaml";
}

SequenceToBagStats writeSequenceBag(const SequenceToBagOptions& options) {
  RecordingRequest request;
  request.sequence_dir = options.sequence_dir;
  Recording recording = openRecording(request);
  SequenceToBagStats stats;
  const std::string camera_topic = cameraTopicOf(options);
  const std::string partial = options.bag_path + ".partial";  // a failed conversion leaves no bag
  try {
    rosbag::Bag bag(partial, rosbag::bagmode::Write);
    while (std::optional<SensorData> data = recording.source->next()) {
      if (const auto* scan = std::get_if<LidarScan>(&*data)) {
        bag.write(options.lidar_topic, rosTime(publishTime(*scan)), toCloud(*scan, options.lidar_frame));
        ++stats.scans;
        stats.points += scan->size();
      } else {
        const auto& frame = std::get<ImageFrame>(*data);
        if (options.image_format == BagImageFormat::kRaw)
          bag.write(camera_topic, rosTime(frame.timestamp), toImage(frame, options.camera_frame));
        else
          bag.write(camera_topic, rosTime(frame.timestamp), toCompressed(frame, options.camera_frame, options.image_format));
        ++stats.images;
      }
    }
    bag.close();
  } catch (const rosbag::BagException& e) {
    fs::remove(partial);
    throw Error(options.bag_path, std::string("cannot write the bag: ") + e.what());
  } catch (...) {
    fs::remove(partial);
    throw;
  }
  fs::rename(partial, options.bag_path);
  stats.preset_path = presetPathForBag(options.bag_path);
  writePreset(options, stats.preset_path);
  return stats;
}

}  // namespace lvslam
