#pragma once
// Anything that streams a recording in time order: a sequence folder, a ROS1
// bag, a simulator. The system consumes this and nothing more specific.
#include <optional>
#include <variant>

#include "lvslam/core/calibration.h"
#include "lvslam/core/image_frame.h"
#include "lvslam/core/lidar_scan.h"

namespace lvslam {

using SensorData = std::variant<ImageFrame, LidarScan>;

// The stamp of an image or a scan.
inline double stampOf(const SensorData& data) {
  return std::visit([](const auto& item) { return item.timestamp; }, data);
}

class SensorSource {
 public:
  virtual ~SensorSource() = default;
  // The next image or scan in time order; none at the end. Throws
  // lvslam::Error on malformed data.
  virtual std::optional<SensorData> next() = 0;
  virtual Calibration calibration() const = 0;
  virtual bool hasCamera() const = 0;
  virtual bool hasLidar() const = 0;
};

}  // namespace lvslam
