#include "lvslam/io/live_source.h"

#include <algorithm>
#include <utility>

namespace lvslam {

namespace {

// Queue order: by stamp, a scan before an image at the same stamp (as the
// sequence and bag readers hand them on).
bool before(const SensorData& a, const SensorData& b) {
  const double ta = stampOf(a), tb = stampOf(b);
  if (ta != tb) return ta < tb;
  return std::holds_alternative<LidarScan>(a) && std::holds_alternative<ImageFrame>(b);
}

}  // namespace

LiveSensorSource::LiveSensorSource(const LiveSourceOptions& options) : options_(options) {
  if (options_.capacity == 0) options_.capacity = 1;
}

LiveSensorSource::Stream& LiveSensorSource::streamOf(const SensorData& data) {
  return std::holds_alternative<ImageFrame>(data) ? camera_ : lidar_;
}

LivePushResult LiveSensorSource::push(SensorData data) {
  LivePushResult result;
  {
    std::lock_guard lock(mutex_);
    if (closed_) return result;  // the run is ending; nothing more is read
    Stream& stream = streamOf(data);
    const double t = stampOf(data);
    if (stream.last_stamp && !(t > *stream.last_stamp)) {
      ++counts_.out_of_order;
      result.verdict = LiveVerdict::kOutOfOrder;
      return result;
    }
    stream.last_stamp = t;
    if (handed_on_until_ && t < *handed_on_until_) {
      ++counts_.late;
      result.verdict = LiveVerdict::kLate;
      return result;
    }
    const auto at = std::upper_bound(items_.begin(), items_.end(), data, before);
    items_.insert(at, std::move(data));
    ++counts_.queued;
    while (items_.size() > options_.capacity) {
      items_.pop_front();
      ++counts_.overflow;
      ++result.dropped_oldest;
    }
  }
  changed_.notify_all();
  return result;
}

void LiveSensorSource::close() {
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
  }
  changed_.notify_all();
}

LiveSourceCounts LiveSensorSource::counts() const {
  std::lock_guard lock(mutex_);
  return counts_;
}

bool LiveSensorSource::headReady() const {
  if (items_.empty()) return false;
  if (closed_) return true;
  const SensorData& head = items_.front();
  const double t = stampOf(head);
  double newest = t;
  for (const Stream* s : {&camera_, &lidar_})
    if (s->last_stamp) newest = std::max(newest, *s->last_stamp);
  const bool head_is_image = std::holds_alternative<ImageFrame>(head);
  // The other sensor may still send something older than the head unless it
  // already sent something at least as new (its stamps only increase).
  const bool other_active = head_is_image ? options_.lidar : options_.camera;
  if (!other_active) return true;
  const Stream& other = head_is_image ? lidar_ : camera_;
  if (other.last_stamp && *other.last_stamp >= t) return true;
  return newest - t >= options_.max_wait_s;  // the other sensor is silent: do not stall
}

std::optional<SensorData> LiveSensorSource::next() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return headReady() || (closed_ && items_.empty()); });
  if (items_.empty()) return std::nullopt;
  SensorData data = std::move(items_.front());
  items_.pop_front();
  handed_on_until_ = stampOf(data);
  ++counts_.handed_on;
  return data;
}

}  // namespace lvslam
