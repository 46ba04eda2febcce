#pragma once
// A SensorSource fed while the system runs, as a robot's driver callbacks
// feed it: items pushed by one thread (the subscriber callbacks), read by the
// pipeline's reading thread in time order. Each sensor's stream arrives in
// its own order and late relative to the other (a sweep is published at its
// end, stamped at its start), so an item is handed on only once every other
// sensor has delivered something at least as late, or has stayed silent for
// `max_wait_s` of message time (a sensor that dropped out must not stall the
// other). The queue is bounded: when the system falls behind, the oldest
// item is dropped, as a live system should rather lag less than lose the
// newest data. Knows nothing of ROS.
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <optional>

#include "lvslam/io/sensor_source.h"

namespace lvslam {

struct LiveSourceOptions {
  Calibration calibration;
  bool camera = true, lidar = true;  // the sensors that will deliver
  std::size_t capacity = 64;         // items held at most (both sensors together)
  double max_wait_s = 0.5;           // message time an item waits for a silent sensor
};

// What became of a pushed item.
enum class LiveVerdict {
  kQueued,
  kOutOfOrder,  // stamp not after its own sensor's previous one: dropped
  kLate,        // stamp before an item already handed on: dropped (the system cannot go back)
};

struct LivePushResult {
  LiveVerdict verdict = LiveVerdict::kQueued;
  std::size_t dropped_oldest = 0;  // items dropped to make room (queue overflow)
};

struct LiveSourceCounts {
  std::size_t queued = 0, out_of_order = 0, late = 0, overflow = 0, handed_on = 0;
};

class LiveSensorSource : public SensorSource {
 public:
  explicit LiveSensorSource(const LiveSourceOptions& options);

  LivePushResult push(SensorData data);
  // No more data: next() hands on what is queued, then reports the end.
  void close();
  LiveSourceCounts counts() const;

  std::optional<SensorData> next() override;  // blocks until an item may go or the source is closed
  Calibration calibration() const override { return options_.calibration; }
  bool hasCamera() const override { return options_.camera; }
  bool hasLidar() const override { return options_.lidar; }

 private:
  struct Stream {
    std::optional<double> last_stamp;  // newest stamp received
  };
  bool headReady() const;  // with mutex_ held
  Stream& streamOf(const SensorData& data);

  LiveSourceOptions options_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<SensorData> items_;  // sorted by stamp, a scan before an image at the same stamp
  Stream camera_, lidar_;
  std::optional<double> handed_on_until_;  // stamp of the last item handed on
  bool closed_ = false;
  LiveSourceCounts counts_;
};

}  // namespace lvslam
