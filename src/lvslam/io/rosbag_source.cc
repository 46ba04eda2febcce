#include "lvslam/io/rosbag_source.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "lvslam/core/error.h"
#include "lvslam/io/pointcloud2_decoder.h"
#include "lvslam/io/rosbag_image.h"
#include "lvslam/io/rosbag_reader.h"

namespace lvslam {

namespace {

constexpr const char* kPointCloud2 = "sensor_msgs/PointCloud2";
constexpr const char* kImage = "sensor_msgs/Image";
constexpr const char* kCompressedImage = "sensor_msgs/CompressedImage";

std::string topicList(const RosbagReader& bag) {
  std::vector<std::string> names;
  for (const auto& t : bag.topics()) names.push_back(fmt::format("{} [{}]", t.topic, t.type));
  return names.empty() ? std::string("none") : fmt::format("{}", fmt::join(names, ", "));
}

// Orders the files by their first message and checks the topic in each.
std::vector<std::string> orderFiles(const std::vector<std::string>& files, const BagSourceOptions& options) {
  if (files.empty()) throw Error("bag", "no bag file given");
  std::vector<std::pair<double, std::string>> by_time;
  std::vector<std::string> missing_lidar, missing_camera;
  for (const std::string& file : files) {
    const RosbagReader bag(file);
    if (!bag.damage().empty())
      spdlog::warn("{}: damaged bag, read up to the damage ({})", file, bag.damage());
    by_time.emplace_back(bag.beginTime(), file);
    const auto check = [&](const std::string& topic, std::vector<std::string>& missing, bool lidar) {
      if (topic.empty()) return;
      const auto info = bag.topic(topic);
      if (!info) {
        missing.push_back(fmt::format("{} (topics: {})", file, topicList(bag)));
        return;
      }
      const bool ok = lidar ? info->type == kPointCloud2 : info->type == kImage || info->type == kCompressedImage;
      if (!ok)
        throw Error(fmt::format("{} topic {}", file, topic),
                    fmt::format("type {} is not {}", info->type,
                                lidar ? kPointCloud2 : "sensor_msgs/Image or sensor_msgs/CompressedImage"));
    };
    check(options.lidar_topic, missing_lidar, true);
    check(options.camera_topic, missing_camera, false);
  }
  if (missing_lidar.size() == files.size())
    throw Error(fmt::format("{}", fmt::join(missing_lidar, "; ")), fmt::format("topic '{}' not found", options.lidar_topic));
  if (missing_camera.size() == files.size())
    throw Error(fmt::format("{}", fmt::join(missing_camera, "; ")), fmt::format("topic '{}' not found", options.camera_topic));
  std::stable_sort(by_time.begin(), by_time.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> ordered;
  for (const auto& [t, file] : by_time) ordered.push_back(file);
  return ordered;
}

}  // namespace

// The messages of one topic across the files, decoded, one ahead.
class BagSource::TopicStream {
 public:
  TopicStream(std::vector<std::string> files, std::string topic) : files_(std::move(files)), topic_(std::move(topic)) {
    fill();
  }

  const std::optional<SensorData>& peek() const { return pending_; }
  std::optional<SensorData> pop() {
    popped_offset_ = pending_offset_;
    have_popped_ = true;
    std::optional<SensorData> out = std::move(pending_);
    pending_.reset();
    fill();
    return out;
  }
  const LidarInfo& lidarInfo() const { return lidar_; }
  std::size_t skipped() const { return skipped_; }
  const std::string& topic() const { return topic_; }
  const std::string& pendingFile() const { return pending_file_; }
  // Stamp minus record time of the message ahead, and of the one popped last
  // (the message ahead's when none was popped yet).
  double pendingOffset() const { return pending_offset_; }
  double poppedOffset() const { return have_popped_ ? popped_offset_ : pending_offset_; }

 private:
  std::optional<BagMessage> nextMessage() {
    while (true) {
      if (bag_) {
        if (auto m = bag_->next()) return m;
        bag_.reset();
      }
      if (next_file_ == files_.size()) return std::nullopt;
      bag_ = std::make_unique<RosbagReader>(files_[next_file_++]);
      bag_->select({topic_});
    }
  }

  SensorData decode(const BagMessage& m) {
    const std::string where = fmt::format("{} topic {}", bag_->path(), topic_);
    if (m.type == kImage) return decodeRosImage(m.data, where);
    if (m.type == kCompressedImage) return decodeRosCompressedImage(m.data, where);
    if (m.type != kPointCloud2) throw Error(where, "unsupported message type " + m.type);
    DecodedScan d = decodePointCloud2(m.data, where);
    if (!first_scan_seen_) {
      first_scan_seen_ = true;
      const LidarScan& s = d.scan;
      lidar_.point_fields = {"x", "y", "z"};
      if (s.has_intensity) lidar_.point_fields.push_back("intensity");
      if (s.has_time) lidar_.point_fields.push_back("time");
      if (s.has_ring) lidar_.point_fields.push_back("ring");
      if (d.time_reference) lidar_.time_reference = *d.time_reference;
    }
    if (d.restamped || (d.time_reference && *d.time_reference != lidar_.time_reference)) {
      if (restamped_++ == 0)
        spdlog::warn("{}: scan at {:.6f}: header stamp is not the sweep {} as in the first scan; restamped "
                     "(further cases are not reported)", where, d.scan.timestamp,
                     lidar_.time_reference == TimeReference::kStart ? "start" : "end");
      restampScan(d.scan, lidar_.time_reference);
    }
    return std::move(d.scan);
  }

  void fill() {
    while (!pending_) {
      const std::optional<BagMessage> m = nextMessage();
      if (!m) return;
      SensorData d = decode(*m);
      const double t = stampOf(d);
      if (have_last_ && !(t > last_t_)) {
        if (skipped_++ == 0)
          spdlog::warn("{} topic {}: stamp {:.9f} does not increase (previous {:.9f}); message skipped "
                       "(further cases are counted, not reported)", bag_->path(), topic_, t, last_t_);
        continue;
      }
      last_t_ = t;
      have_last_ = true;
      pending_ = std::move(d);
      pending_offset_ = t - m->record_time;
      pending_file_ = bag_->path();
    }
  }

  std::vector<std::string> files_;
  std::string topic_;
  std::size_t next_file_ = 0;
  std::unique_ptr<RosbagReader> bag_;
  std::optional<SensorData> pending_;
  std::string pending_file_;
  double pending_offset_ = 0.0, popped_offset_ = 0.0;
  bool have_popped_ = false;
  double last_t_ = 0.0;
  bool have_last_ = false;
  bool first_scan_seen_ = false;
  LidarInfo lidar_;
  std::size_t skipped_ = 0, restamped_ = 0;
};

BagSource::BagSource(const std::vector<std::string>& files, const BagSourceOptions& options)
    : options_(options), files_(orderFiles(files, options)) {
  if (options.lidar_topic.empty() && options.camera_topic.empty())
    throw Error(fmt::format("{}", fmt::join(files, ", ")), "no topic chosen: give a LiDAR topic, a camera topic, or both");
  if (!options.lidar_topic.empty()) lidar_ = std::make_unique<TopicStream>(files_, options.lidar_topic);
  if (!options.camera_topic.empty()) camera_ = std::make_unique<TopicStream>(files_, options.camera_topic);
}

BagSource::~BagSource() = default;

// Compares the two messages ahead: their stamps' offsets to the record time
// keep their difference unless a clock jumped; the stream whose offset moved
// from its own last one is the one that jumped.
void BagSource::checkClocks() {
  const double difference = lidar_->pendingOffset() - camera_->pendingOffset();
  if (clock_difference_ && std::abs(difference - *clock_difference_) > kMaxClockStep) {
    const double lidar_step = lidar_->pendingOffset() - lidar_->poppedOffset();
    const double camera_step = camera_->pendingOffset() - camera_->poppedOffset();
    const bool camera_jumped = std::abs(camera_step) > std::abs(lidar_step);
    const TopicStream& jumped = camera_jumped ? *camera_ : *lidar_;
    const TopicStream& other = camera_jumped ? *lidar_ : *camera_;
    throw Error(fmt::format("{} topic {}", jumped.pendingFile(), jumped.topic()),
                fmt::format("time stamp {:.6f} jumps by {:+.3f} s against its record time while the stamps of topic {} "
                            "do not: one sensor's clock jumped, and stamps that no longer agree cannot be merged",
                            stampOf(*jumped.peek()), camera_jumped ? camera_step : lidar_step, other.topic()));
  }
  clock_difference_ = difference;
}

std::optional<SensorData> BagSource::next() {
  const bool lidar_ready = lidar_ && lidar_->peek();
  const bool camera_ready = camera_ && camera_->peek();
  if (lidar_ready && camera_ready) checkClocks();
  if (lidar_ready && camera_ready)  // a scan before an image at the same stamp, as SequenceReader
    return stampOf(*lidar_->peek()) <= stampOf(*camera_->peek()) ? lidar_->pop() : camera_->pop();
  if (lidar_ready) return lidar_->pop();
  if (camera_ready) return camera_->pop();
  return std::nullopt;
}

LidarInfo BagSource::lidarInfo() const {
  LidarInfo info = lidar_ ? lidar_->lidarInfo() : LidarInfo{};
  info.rings = options_.lidar.rings;
  info.rate_hz = options_.lidar.rate_hz;
  return info;
}

std::size_t BagSource::skippedMessages() const {
  return (lidar_ ? lidar_->skipped() : 0) + (camera_ ? camera_->skipped() : 0);
}

std::unique_ptr<SensorSource> openBagSource(const std::vector<std::string>& files, const BagSourceOptions& options) {
  return std::make_unique<BagSource>(files, options);
}

}  // namespace lvslam
