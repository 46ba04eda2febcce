#include "lvslam/loop/loop_closure.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>
#include <fmt/format.h>

#include "lvslam/loop/loop_candidates.h"

namespace lvslam::loop {

namespace {

constexpr double kDegree = M_PI / 180.0;
// Keyframes made by turning on the spot still drift a little.
constexpr double kMinEdgePath = 0.25;  // metres

Matrix6d diagonalCovariance(double sigma_m, double sigma_rad) {
  Vector6d variances;
  variances << Eigen::Vector3d::Constant(sigma_m * sigma_m), Eigen::Vector3d::Constant(sigma_rad * sigma_rad);
  return variances.asDiagonal();
}

std::vector<Eigen::Vector3f> positionsOf(const std::vector<lidar::FeaturePoint>& points) {
  std::vector<Eigen::Vector3f> p;
  p.reserve(points.size());
  for (const lidar::FeaturePoint& point : points) p.push_back(point.p);
  return p;
}

}  // namespace

std::size_t LoopClosureResult::accepted() const {
  return static_cast<std::size_t>(std::count_if(candidates.begin(), candidates.end(),
                                                [](const LoopCandidateRecord& c) { return c.reason.empty(); }));
}

LoopClosure::LoopClosure(const LoopClosureConfig& config, const lidar::RegistrationConfig& registration)
    : config_(config), registration_(registration) {}

std::vector<SubmapScan> LoopClosure::submapAround(int candidate) const {
  const int first = std::max(0, candidate - config_.submap_keyframes);
  const int last = std::min(static_cast<int>(keyframes_.size()) - 2, candidate + config_.submap_keyframes);
  const Eigen::Isometry3d T_candidate_odom = keyframes_[static_cast<std::size_t>(candidate)].T_odom_lidar.inverse();
  std::vector<SubmapScan> submap;
  for (int k = first; k <= last; ++k) {
    const LoopKeyframe& kf = keyframes_[static_cast<std::size_t>(k)];
    submap.push_back({T_candidate_odom * kf.T_odom_lidar, &kf.points});
  }
  return submap;
}

bool LoopClosure::addKeyframe(LoopKeyframe keyframe) {
  descriptors_.push_back(makeScanContext(positionsOf(keyframe.points), config_.scan_context));
  path_lengths_.push_back(keyframe.path_length);
  keyframes_.push_back(std::move(keyframe));
  const auto found =
      findLoopCandidate(descriptors_, path_lengths_, config_.exclude_recent_path, config_.ring_key_candidates);
  if (!found) return false;
  const int query = static_cast<int>(keyframes_.size()) - 1;
  LoopCandidateRecord record;
  record.query = query;
  record.candidate = found->index;
  record.query_t = keyframes_.back().t;
  record.candidate_t = keyframes_[static_cast<std::size_t>(found->index)].t;
  record.ring_key_distance = found->ring_key_distance;
  record.descriptor_distance = found->match.distance;
  record.yaw = found->match.yaw;
  if (found->match.distance > config_.max_descriptor_distance) {
    record.reason = fmt::format("descriptor distance {:.3f} (> {:.3f})", found->match.distance,
                                config_.max_descriptor_distance);
    candidates_.push_back(std::move(record));
    return false;
  }
  record.verified = true;
  record.verification =
      verifyLoop(keyframes_.back().points, submapAround(found->index), found->match.yaw, config_, registration_);
  record.reason = record.verification.reason.empty() ? offOdometry(found->index, record.verification.T_candidate_query)
                                                      : record.verification.reason;
  const bool accepted = record.reason.empty();
  if (accepted) {
    GraphEdge edge;
    edge.from = found->index;
    edge.to = query;
    edge.T_from_to = record.verification.T_candidate_query;
    const Matrix6d covariance = record.verification.information.inverse() +
                                diagonalCovariance(config_.loop_sigma_m, config_.loop_sigma_deg * kDegree);
    edge.information = covariance.inverse();
    edge.robust = true;
    loop_records_.push_back(candidates_.size());
    loop_edges_.push_back(edge);
  }
  candidates_.push_back(std::move(record));
  return accepted;
}

// A loop must agree with the odometry within the drift the graph allows it
// over the path between the two keyframes (the odometry's own uncertainty,
// as LIO-SAM searches candidates within a radius of the odometry's pose):
// scenes with a symmetry or a repeated room register well in a wrong place.
std::string LoopClosure::offOdometry(int candidate, const Eigen::Isometry3d& T_candidate_query) const {
  const LoopKeyframe& from = keyframes_[static_cast<std::size_t>(candidate)];
  const LoopKeyframe& to = keyframes_.back();
  const Eigen::Isometry3d offset = (from.T_odom_lidar.inverse() * to.T_odom_lidar).inverse() * T_candidate_query;
  const double sqrt_path = std::sqrt(std::max(to.path_length - from.path_length, kMinEdgePath));
  const double max_m = config_.odometry_gate_sigmas * config_.odometry_sigma_m * sqrt_path;
  const double max_deg = config_.odometry_gate_sigmas * config_.odometry_sigma_deg * sqrt_path;
  const double off_m = offset.translation().norm();
  const double off_deg = rotationAngle(offset) / kDegree;
  if (off_m <= max_m && off_deg <= max_deg) return "";
  return fmt::format("off the odometry by {:.2f} m, {:.1f} deg (> {:.2f} m, {:.1f} deg)", off_m, off_deg, max_m,
                     max_deg);
}

GraphEdge LoopClosure::odometryEdge(int to) const {
  const LoopKeyframe& a = keyframes_[static_cast<std::size_t>(to - 1)];
  const LoopKeyframe& b = keyframes_[static_cast<std::size_t>(to)];
  const double sqrt_path = std::sqrt(std::max(b.path_length - a.path_length, kMinEdgePath));
  GraphEdge edge;
  edge.from = to - 1;
  edge.to = to;
  edge.T_from_to = a.T_odom_lidar.inverse() * b.T_odom_lidar;
  edge.information =
      diagonalCovariance(config_.odometry_sigma_m * sqrt_path, config_.odometry_sigma_deg * kDegree * sqrt_path)
          .inverse();
  return edge;
}

LoopClosureResult LoopClosure::solve() const {
  LoopClosureResult result;
  result.candidates = candidates_;
  for (const LoopKeyframe& kf : keyframes_) {
    result.keyframe_times.push_back(kf.t);
    result.T_odom_lidar.push_back(kf.T_odom_lidar);
  }
  std::vector<GraphEdge> edges;
  for (int k = 1; k < static_cast<int>(keyframes_.size()); ++k) edges.push_back(odometryEdge(k));
  const std::size_t first_loop = edges.size();
  edges.insert(edges.end(), loop_edges_.begin(), loop_edges_.end());
  const GraphSolution solution = solveGlobalPoseGraph(result.T_odom_lidar, edges, config_.loop_kernel);
  result.solved = solution.solved;
  result.T_odom_lidar_corrected = solution.solved ? solution.poses : result.T_odom_lidar;
  for (std::size_t k = 0; k < loop_records_.size(); ++k)
    result.candidates[loop_records_[k]].graph_weight = solution.edge_weights[first_loop + k];
  return result;
}

}  // namespace lvslam::loop
