#include "topic_input.h"

#include <fmt/format.h>

#include "lvslam/core/error.h"
#include "lvslam/io/pointcloud2_decoder.h"
#include "lvslam/io/rosbag_image.h"

namespace lvslam::ros_node {

namespace {

// Encodings decodeRosImage reads; another one is the "unsupported encoding" kind.
bool readableEncoding(const std::string& encoding) {
  return encoding == "mono8" || encoding == "bgr8" || encoding == "rgb8";
}

// Deep enough for a burst of a few hundred ms; the live source does the real buffering.
constexpr std::uint32_t kSubscriberQueue = 20;

}  // namespace

TopicInput::TopicInput(ros::NodeHandle& nh, const NodeParams& params, LiveSensorSource& source,
                       InputProblems& problems, Hooks hooks)
    : params_(params), source_(source), problems_(problems), hooks_(std::move(hooks)) {
  // No Nagle: a scan must not wait for the next packet.
  const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
  if (!params.lidar_topic.empty())
    lidar_sub_ = nh.subscribe<PointCloud2>(params.lidar_topic, kSubscriberQueue, &TopicInput::onCloud, this, hints);
  if (!params.camera_topic.empty()) {
    if (params.camera_compressed)
      camera_sub_ = nh.subscribe<CompressedImage>(params.camera_topic, kSubscriberQueue, &TopicInput::onCompressedImage,
                                                  this, hints);
    else
      camera_sub_ = nh.subscribe<Image>(params.camera_topic, kSubscriberQueue, &TopicInput::onImage, this, hints);
  }
}

void TopicInput::shutdown() {
  lidar_sub_.shutdown();
  camera_sub_.shutdown();
}

void TopicInput::onCloud(const boost::shared_ptr<const PointCloud2>& msg) {
  const std::string where = "topic " + params_.lidar_topic;
  DecodedScan decoded;
  try {
    decoded = decodePointCloud2(serialize(*msg), where);
  } catch (const Error& e) {
    problems_.report("undecodable cloud", e.what());
    return;
  }
  LidarScan& scan = decoded.scan;
  if (scan.empty()) {
    problems_.report("empty cloud", fmt::format("{}: scan at {:.6f} has no valid point ({} of {} dropped)", where,
                                                scan.timestamp, decoded.invalid_points, decoded.total_points));
    return;
  }
  // The LiDAR subsystem deskews each sweep by its points' own times.
  if (!scan.has_time || !decoded.time_reference) {
    problems_.report("cloud without per-point time",
                     fmt::format("{}: scan at {:.6f} has no time field (time, t, timestamp or time_sec/time_nsec)",
                                 where, scan.timestamp));
    return;
  }
  if (!time_reference_) time_reference_ = *decoded.time_reference;
  if (decoded.restamped || *decoded.time_reference != *time_reference_) restampScan(scan, *time_reference_);
  if (hooks_.scan_accepted) hooks_.scan_accepted(scan);
  push(std::move(scan), where);
}

void TopicInput::onImage(const boost::shared_ptr<const Image>& msg) {
  const std::string where = "topic " + params_.camera_topic;
  const double stamp = rosmsg::toSeconds(msg->header.stamp);
  if (hooks_.image_arrived) hooks_.image_arrived(stamp);
  const std::string encoding(msg->encoding.begin(), msg->encoding.end());
  if (!readableEncoding(encoding)) {
    problems_.report("unsupported image encoding",
                     fmt::format("{}: image at {:.6f} is '{}'; lvslam reads mono8, bgr8 and rgb8", where, stamp, encoding));
    return;
  }
  try {
    acceptImage(decodeRosImage(serialize(*msg), where), where);
  } catch (const Error& e) {
    problems_.report("undecodable image", e.what());
  }
}

void TopicInput::onCompressedImage(const boost::shared_ptr<const CompressedImage>& msg) {
  const std::string where = "topic " + params_.camera_topic;
  if (hooks_.image_arrived) hooks_.image_arrived(rosmsg::toSeconds(msg->header.stamp));
  try {
    acceptImage(decodeRosCompressedImage(serialize(*msg), where), where);
  } catch (const Error& e) {
    problems_.report("undecodable image", e.what());
  }
}

void TopicInput::acceptImage(ImageFrame frame, const std::string& where) {
  const PinholeCamera& camera = params_.preset.camera->camera;
  if (frame.image.cols != camera.width() || frame.image.rows != camera.height()) {
    problems_.report("image size not the calibration's",
                     fmt::format("{}: image at {:.6f} is {}x{}, the preset's camera {}x{}", where, frame.timestamp,
                                 frame.image.cols, frame.image.rows, camera.width(), camera.height()));
    return;
  }
  push(std::move(frame), where);
}

void TopicInput::push(SensorData data, const std::string& where) {
  const double t = stampOf(data);
  const LivePushResult r = source_.push(std::move(data));
  if (r.verdict == LiveVerdict::kOutOfOrder)
    problems_.report("out of order", fmt::format("{}: stamp {:.6f} is not after the topic's previous one", where, t));
  if (r.verdict == LiveVerdict::kLate)
    problems_.report("late", fmt::format("{}: stamp {:.6f} is before data the system already took", where, t));
  if (r.dropped_oldest > 0)
    problems_.report("queue overflow", fmt::format("the system is behind: {} items queued (~queue_size); the oldest "
                                                   "is dropped for each new one", params_.queue_size));
}

}  // namespace lvslam::ros_node
