#include "lvslam/visual/match/line_matcher.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "lvslam/visual/match/descriptor_distance.h"
#include "lvslam/visual/match/unique_matches.h"

namespace lvslam::visual {

namespace {

struct Best {
  int index = -1;
  int distance = std::numeric_limits<int>::max();
  int second = std::numeric_limits<int>::max();
  void offer(int j, int d) {
    if (d < distance) {
      second = distance;
      distance = d;
      index = j;
    } else if (d < second) {
      second = d;
    }
  }
  bool acceptable(const LineMatcherConfig& c) const {
    return index >= 0 && distance <= c.max_distance &&
           (second == std::numeric_limits<int>::max() || distance < c.ratio * second);
  }
};

bool descriptorsUsable(const cv::Mat& d, size_t rows) {
  return d.rows == static_cast<int>(rows) && d.cols == 32 && d.type() == CV_8U;
}

}  // namespace

double segmentAngleDeg(const Eigen::Vector2d& a0, const Eigen::Vector2d& a1, const Eigen::Vector2d& b0,
                       const Eigen::Vector2d& b1) {
  const Eigen::Vector2d u = (a1 - a0).normalized(), v = (b1 - b0).normalized();
  return std::acos(std::min(1.0, std::abs(u.dot(v)))) * 180.0 / M_PI;
}

std::vector<LineMatch> matchLines(const FeatureFrame& a, const FeatureFrame& b, const LineMatcherConfig& config) {
  std::vector<LineMatch> matches;
  if (!descriptorsUsable(a.line_descriptors, a.lines.size()) || !descriptorsUsable(b.line_descriptors, b.lines.size())) {
    return matches;
  }
  for (size_t i = 0; i < a.lines.size(); ++i) {
    const LineSegment& s = a.lines[i];
    const Eigen::Vector2d mid = 0.5 * (s.start + s.end);
    Best best;
    for (size_t j = 0; j < b.lines.size(); ++j) {
      const LineSegment& t = b.lines[j];
      if ((0.5 * (t.start + t.end) - mid).norm() > config.max_offset_px) continue;
      if (segmentAngleDeg(s.start, s.end, t.start, t.end) > config.max_angle_deg) continue;
      best.offer(static_cast<int>(j), descriptorDistance(a.line_descriptors, static_cast<int>(i), b.line_descriptors,
                                                         static_cast<int>(j)));
    }
    if (best.acceptable(config)) matches.push_back({static_cast<int>(i), best.index, best.distance});
  }
  return uniqueMatches(matches, b.lines.size());
}

std::vector<LineMatch> matchLinesByProjection(const std::vector<ProjectedLine>& projected, const FeatureFrame& frame,
                                              const LineMatcherConfig& config) {
  std::vector<LineMatch> matches;
  if (!descriptorsUsable(frame.line_descriptors, frame.lines.size())) return matches;
  for (size_t i = 0; i < projected.size(); ++i) {
    const ProjectedLine& p = projected[i];
    if (p.descriptor.empty() || !p.start.allFinite() || !p.end.allFinite()) continue;
    const Eigen::Vector3d l = lineCoefficients(p.start, p.end);
    if (l.isZero()) continue;
    const Eigen::Vector2d mid = 0.5 * (p.start + p.end);
    const double half_length = 0.5 * (p.end - p.start).norm();
    Best best;
    for (size_t j = 0; j < frame.lines.size(); ++j) {
      const LineSegment& t = frame.lines[j];
      if (std::abs(l.dot(t.start.homogeneous())) > config.max_line_distance_px ||
          std::abs(l.dot(t.end.homogeneous())) > config.max_line_distance_px) {
        continue;
      }
      // The segments must overlap along the line (midpoints within both half lengths).
      if ((0.5 * (t.start + t.end) - mid).norm() > half_length + 0.5 * t.length) continue;
      if (segmentAngleDeg(p.start, p.end, t.start, t.end) > config.max_angle_deg) continue;
      best.offer(static_cast<int>(j), hammingDistance256(p.descriptor.ptr<uint8_t>(0),
                                                         frame.line_descriptors.ptr<uint8_t>(static_cast<int>(j))));
    }
    if (best.acceptable(config)) matches.push_back({static_cast<int>(i), best.index, best.distance});
  }
  return uniqueMatches(matches, frame.lines.size());
}

}  // namespace lvslam::visual
