#pragma once
// The detection module (paper, "System Overview"): judges the visual
// subsystem's health every camera frame from its own figures (tracking
// state, tracked features, inliers, image brightness and contrast, metric
// scale) and decides whether its estimate may enter the output. It drops
// vision at once when it fails and admits it again only after it has been
// healthy for a while (the first map, before any failure, at once). Whether
// vision is *better* than the LiDAR is never decided here: the online
// estimator weighs both by their own uncertainty.
#include <optional>
#include <string>
#include <vector>

namespace lvslam::system {

enum class VisualState { kInitializing, kTracking, kLost };

struct VisualHealth {
  double t = 0.0;
  VisualState state = VisualState::kInitializing;
  int tracked_points = 0;
  int tracked_lines = 0;
  double inlier_ratio = 0.0;
  double brightness = 0.0;  // image mean, 0..255
  double contrast = 0.0;    // image standard deviation, 0..255
  bool metric = true;       // the visual map's scale came from LiDAR depth
};

struct DetectionConfig {
  int min_tracked_points = 40;
  int min_tracked_lines = 0;
  double min_inlier_ratio = 0.5;
  double min_brightness = 20.0, max_brightness = 245.0;
  double min_contrast = 8.0;
  int frames_to_recover = 10;           // consecutive healthy frames before vision is believed again after a failure
  // Back in a visual map after the LiDAR, the output rejoins the map's first
  // anchor by at most this much per frame (system/output_trajectory.h).
  double rejoin_step_m = 0.002;
  double rejoin_step_deg = 0.05;
};

enum class OutputSource { kVisual, kLidar };

struct SwitchEvent {
  double t = 0.0;
  OutputSource to = OutputSource::kLidar;
  std::string reason;
};

class DetectionModule {
 public:
  explicit DetectionModule(const DetectionConfig& config) : config_(config) {}

  // One camera frame: kVisual while vision is admitted.
  OutputSource update(const VisualHealth& health);

  OutputSource source() const { return source_; }
  const std::vector<SwitchEvent>& switches() const { return switches_; }
  // Why the last frame counted as unhealthy ("" when it was healthy).
  const std::string& lastProblem() const { return last_problem_; }

 private:
  std::string problemWith(const VisualHealth& h) const;

  DetectionConfig config_;
  OutputSource source_ = OutputSource::kLidar;  // until vision has proven itself
  int healthy_streak_ = 0;
  bool failed_ = false;  // unhealthy for a reason other than waiting for the first map
  std::string last_problem_;
  std::vector<SwitchEvent> switches_;
};

}  // namespace lvslam::system
