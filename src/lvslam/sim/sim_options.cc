#include "lvslam/sim/sim_options.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "lvslam/core/error.h"
#include "lvslam/core/timestamp.h"

namespace lvslam::sim {

namespace {

// Two comma-separated finite numbers.
std::vector<double> parsePair(const std::string& text, const std::string& option, const std::string& shape) {
  const auto comma = text.find(',');
  double a = 0.0, b = 0.0;
  if (comma == std::string::npos || !parseTimestamp(text.substr(0, comma), a) ||
      !parseTimestamp(text.substr(comma + 1), b))
    throw Error(option, "expected " + shape + " (two numbers separated by a comma), got '" + text + "'");
  return {a, b};
}

}  // namespace

void validate(const SimOptions& options) {
  const std::vector<std::string> scenarios{"room", "hall", "gate", "corridor", "yard", "office", "atrium", "twins"};
  if (std::find(scenarios.begin(), scenarios.end(), options.scenario) == scenarios.end())
    throw Error("--scenario", "unknown scenario '" + options.scenario +
                                  "' (expected room, hall, gate, corridor, yard, office, atrium or twins)");
  if (options.lidar != "vlp32c" && options.lidar != "vlp16")
    throw Error("--lidar", "unknown LiDAR '" + options.lidar + "' (expected vlp32c or vlp16)");
  if (options.blur_samples < 2 || options.blur_samples > 16)
    throw Error("blur_samples", "must be between 2 and 16 sub-exposures");
  if (options.people < 0 || options.people > kMaxPeople)
    throw Error("--people", "must be between 0 and " + std::to_string(kMaxPeople));
  if (!std::isfinite(options.speed_scale) || options.speed_scale <= 0.0 || options.speed_scale > 3.0)
    throw Error("--speed-scale", "must be in (0, 3]");
  if (!std::isfinite(options.exposure_scale) || options.exposure_scale <= 0.0 || options.exposure_scale > 5.0)
    throw Error("--exposure-scale", "must be in (0, 5]");
  if (!std::isfinite(options.duration) || options.duration <= 0.0)
    throw Error("--duration", "must be a positive number of seconds");
  if (options.duration > 3600.0) throw Error("--duration", "at most 3600 seconds");
  if (const auto& e = options.extrinsic_error) {
    if (!std::isfinite(e->rotation_deg) || !std::isfinite(e->translation_m) || e->rotation_deg < 0.0 ||
        e->rotation_deg > 180.0 || e->translation_m < 0.0)
      throw Error("--extrinsic-error", "DEG must be in [0, 180] and M non-negative");
  }
  const auto checkInterval = [](const std::optional<TimeInterval>& interval, const char* option) {
    if (interval && (!std::isfinite(interval->begin) || !std::isfinite(interval->end) || interval->begin < 0.0 ||
                     interval->end < interval->begin))
      throw Error(option, "expected 0 <= T0 <= T1 (seconds from the sequence start)");
  };
  checkInterval(options.camera_blackout, "--camera-blackout");
  checkInterval(options.lidar_dropout, "--lidar-dropout");
  if (!std::isfinite(options.start_time) || options.start_time < 0.0)
    throw Error("start_time", "must be a non-negative number of seconds");
}

ExtrinsicError parseExtrinsicError(const std::string& text) {
  const auto v = parsePair(text, "--extrinsic-error", "DEG,M");
  ExtrinsicError e{v[0], v[1]};
  SimOptions probe;
  probe.extrinsic_error = e;
  validate(probe);
  return e;
}

TimeInterval parseTimeInterval(const std::string& text, const std::string& option) {
  const auto v = parsePair(text, option, "T0,T1");
  if (v[0] < 0.0 || v[1] < v[0]) throw Error(option, "expected 0 <= T0 <= T1, got '" + text + "'");
  return {v[0], v[1]};
}

}  // namespace lvslam::sim
