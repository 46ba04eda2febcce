#include "lvslam/eval/line_accuracy.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lvslam::eval {

double distanceToSegment(const Eigen::Vector3d& p, const TrueSegment& s) {
  const Eigen::Vector3d ab = s.b - s.a;
  const double len2 = ab.squaredNorm();
  const double u = len2 > 0.0 ? std::clamp((p - s.a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (s.a + u * ab - p).norm();
}

double distanceToLine(const Eigen::Vector3d& p, const TrueSegment& s) {
  const Eigen::Vector3d ab = s.b - s.a;
  const double len = ab.norm();
  if (len <= 0.0) return (p - s.a).norm();
  return ab.cross(p - s.a).norm() / len;
}

std::optional<LineMatch> matchToNearestSegment(const Eigen::Vector3d& A, const Eigen::Vector3d& B,
                                               const std::vector<TrueSegment>& truth) {
  const Eigen::Vector3d mid = 0.5 * (A + B);
  double best = std::numeric_limits<double>::infinity();
  std::optional<LineMatch> match;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const double d = distanceToSegment(A, truth[i]) + distanceToSegment(mid, truth[i]) + distanceToSegment(B, truth[i]);
    if (!(d < best)) continue;
    best = d;
    match = LineMatch{i, {0.0, 0.0}, 0.0};
  }
  if (!match) return match;
  const TrueSegment& s = truth[match->segment];
  match->endpoint_distance[0] = distanceToLine(A, s);
  match->endpoint_distance[1] = distanceToLine(B, s);
  const Eigen::Vector3d d_true = (s.b - s.a).normalized();
  const Eigen::Vector3d d_line = (B - A).normalized();
  // Sign-less angle, stable near zero through the cross product.
  match->direction_error_deg = std::atan2(d_true.cross(d_line).norm(), std::abs(d_true.dot(d_line))) * 180.0 / M_PI;
  return match;
}

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(std::clamp(q, 0.0, 1.0) * static_cast<double>(values.size() - 1) + 0.5);
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

AccuracySummary summarize(const std::vector<LineMatch>& matches) {
  AccuracySummary s;
  s.lines = matches.size();
  std::vector<double> distances, angles;
  for (const LineMatch& m : matches) {
    distances.push_back(m.endpoint_distance[0]);
    distances.push_back(m.endpoint_distance[1]);
    angles.push_back(m.direction_error_deg);
  }
  s.median_endpoint_distance = quantile(distances, 0.5);
  s.p90_endpoint_distance = quantile(distances, 0.9);
  s.median_direction_error_deg = quantile(angles, 0.5);
  s.p90_direction_error_deg = quantile(angles, 0.9);
  return s;
}

}  // namespace lvslam::eval
