#include "lvslam/system/detection/detection_module.h"

#include <fmt/format.h>

namespace lvslam::system {

namespace {

std::string imageProblem(const VisualHealth& h, const DetectionConfig& c) {
  if (h.brightness < c.min_brightness) return fmt::format("image too dark (mean {:.0f})", h.brightness);
  if (h.brightness > c.max_brightness) return fmt::format("image saturated (mean {:.0f})", h.brightness);
  if (h.contrast < c.min_contrast) return fmt::format("image without contrast (std {:.1f})", h.contrast);
  return "";
}

}  // namespace

std::string DetectionModule::problemWith(const VisualHealth& h) const {
  const DetectionConfig& c = config_;
  // Image first: a dark or washed-out image explains everything after it.
  if (std::string image = imageProblem(h, c); !image.empty()) return image;
  if (h.state == VisualState::kLost) return "visual tracking lost";
  if (h.state == VisualState::kInitializing) return "visual subsystem initializing";
  if (!h.metric) return "visual map without metric scale (no LiDAR depth at its start)";
  if (h.tracked_points < c.min_tracked_points)
    return fmt::format("{} tracked points (< {})", h.tracked_points, c.min_tracked_points);
  if (h.tracked_lines < c.min_tracked_lines)
    return fmt::format("{} tracked lines (< {})", h.tracked_lines, c.min_tracked_lines);
  if (h.inlier_ratio < c.min_inlier_ratio)
    return fmt::format("inlier ratio {:.2f} (< {:.2f})", h.inlier_ratio, c.min_inlier_ratio);
  return "";
}

OutputSource DetectionModule::update(const VisualHealth& health) {
  last_problem_ = problemWith(health);
  if (!last_problem_.empty()) {
    healthy_streak_ = 0;
    // Waiting for the first map with good images is not a failure; anything else is.
    const bool waiting = health.state == VisualState::kInitializing && imageProblem(health, config_).empty();
    failed_ = failed_ || !waiting || !switches_.empty();
    if (source_ == OutputSource::kVisual) {
      source_ = OutputSource::kLidar;
      switches_.push_back({health.t, OutputSource::kLidar, last_problem_});
    }
    return source_;
  }
  ++healthy_streak_;
  // Returning after a failure needs a streak of healthy frames, not one good
  // frame; a first map that has not failed yet is admitted at once.
  if (source_ == OutputSource::kLidar && (!failed_ || healthy_streak_ >= config_.frames_to_recover)) {
    source_ = OutputSource::kVisual;
    switches_.push_back({health.t, OutputSource::kVisual,
                         fmt::format("visual tracking healthy for {} frames", healthy_streak_)});
  }
  return source_;
}

}  // namespace lvslam::system
