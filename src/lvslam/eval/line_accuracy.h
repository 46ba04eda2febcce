#pragma once
// Accuracy of fusion lines against known true 3D line segments (the
// simulator's World::edges()): each line is matched to the nearest true
// segment, then its endpoints' distances to that segment's infinite line and
// its direction error are measured.
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace lvslam::eval {

struct TrueSegment {
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
};

struct LineMatch {
  std::size_t segment = 0;               // index into the true segments
  double endpoint_distance[2] = {0, 0};  // metres, A and B to the true line
  double direction_error_deg = 0.0;      // sign-less angle between the directions
};

// Distance from p to the finite segment [a, b].
double distanceToSegment(const Eigen::Vector3d& p, const TrueSegment& s);
// Distance from p to the infinite line through the segment.
double distanceToLine(const Eigen::Vector3d& p, const TrueSegment& s);

// The true segment nearest to the line A-B: the smallest mean distance of A,
// the midpoint and B to the finite segment. None without segments.
std::optional<LineMatch> matchToNearestSegment(const Eigen::Vector3d& A, const Eigen::Vector3d& B,
                                               const std::vector<TrueSegment>& truth);

struct AccuracySummary {
  std::size_t lines = 0;
  double median_endpoint_distance = 0.0;  // metres, over all endpoints
  double p90_endpoint_distance = 0.0;
  double median_direction_error_deg = 0.0;
  double p90_direction_error_deg = 0.0;
};
AccuracySummary summarize(const std::vector<LineMatch>& matches);

// The q-quantile (0..1) of the values (nearest rank); 0 when empty.
double quantile(std::vector<double> values, double q);

}  // namespace lvslam::eval
