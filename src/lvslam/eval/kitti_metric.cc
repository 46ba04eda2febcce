#include "lvslam/eval/kitti_metric.h"

#include <numbers>

#include <fmt/format.h>

#include "lvslam/core/error.h"
#include "lvslam/core/se3.h"

namespace lvslam::eval {

namespace {

// Path length from pose 0 to each pose (devkit trajectoryDistances).
std::vector<double> pathDistances(const std::vector<Eigen::Isometry3d>& poses) {
  std::vector<double> distances(poses.size(), 0.0);
  for (std::size_t i = 1; i < poses.size(); ++i)
    distances[i] =
        distances[i - 1] + (poses[i].translation() - poses[i - 1].translation()).norm();
  return distances;
}

// First frame whose path exceeds the start's by more than length, or none
// (devkit lastFrameFromSegmentLength).
std::size_t lastFrameOfSegment(const std::vector<double>& distances, std::size_t first,
                               double length) {
  for (std::size_t i = first; i < distances.size(); ++i)
    if (distances[i] > distances[first] + length) return i;
  return distances.size();
}

}  // namespace

KittiMetric computeKittiMetric(const std::vector<Eigen::Isometry3d>& gt,
                               const std::vector<Eigen::Isometry3d>& est,
                               const std::vector<double>& lengths_m, std::size_t step) {
  if (gt.size() != est.size() || step == 0)
    throw Error("KITTI metric", fmt::format("{} ground-truth poses, {} estimated, step {}",
                                            gt.size(), est.size(), step));
  KittiMetric metric;
  metric.lengths_m = lengths_m;
  const std::vector<double> distances = pathDistances(gt);
  double translation_sum = 0.0;
  double rotation_sum = 0.0;
  for (std::size_t first = 0; first < gt.size(); first += step) {
    for (const double length : lengths_m) {
      const std::size_t last = lastFrameOfSegment(distances, first, length);
      if (last == distances.size()) continue;
      const Eigen::Isometry3d gt_motion = gt[first].inverse() * gt[last];
      const Eigen::Isometry3d est_motion = est[first].inverse() * est[last];
      const Eigen::Isometry3d error = est_motion.inverse() * gt_motion;
      translation_sum += error.translation().norm() / length;
      rotation_sum += rotationAngle(error) / length;
      ++metric.segments;
    }
  }
  if (metric.segments == 0) return metric;
  const double n = static_cast<double>(metric.segments);
  metric.translation_percent = 100.0 * translation_sum / n;
  metric.rotation_deg_per_m = rotation_sum / n * 180.0 / std::numbers::pi;
  return metric;
}

}  // namespace lvslam::eval
