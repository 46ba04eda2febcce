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

std::string offOdometry(const Eigen::Isometry3d& T_odom_from, const Eigen::Isometry3d& T_odom_to, double path,
                        const Eigen::Isometry3d& T_candidate_query, const LoopClosureConfig& config) {
  return offByDrift((T_odom_from.inverse() * T_odom_to).inverse() * T_candidate_query, path, config);
}

// The odometry's drift per sqrt(m) of path between keyframes to - 1 and to.
GraphEdge odometryEdge(const LoopClosureResult& result, int to, const LoopClosureConfig& config) {
  const auto a = static_cast<std::size_t>(to - 1), b = static_cast<std::size_t>(to);
  const double sqrt_path = std::sqrt(std::max(result.path_lengths[b] - result.path_lengths[a], kMinEdgePath));
  GraphEdge edge;
  edge.from = to - 1;
  edge.to = to;
  edge.T_from_to = result.T_odom_lidar[a].inverse() * result.T_odom_lidar[b];
  edge.information =
      diagonalCovariance(config.odometry_sigma_m * sqrt_path, config.odometry_sigma_deg * kDegree * sqrt_path)
          .inverse();
  return edge;
}

// An accepted loop: the ICP's own covariance plus the configured floor, robust.
GraphEdge loopEdge(const LoopCandidateRecord& c, const LoopClosureConfig& config) {
  GraphEdge edge;
  edge.from = c.candidate;
  edge.to = c.query;
  edge.T_from_to = c.verification.T_candidate_query;
  const Matrix6d covariance =
      c.verification.information.inverse() + diagonalCovariance(config.loop_sigma_m, config.loop_sigma_deg * kDegree);
  edge.information = covariance.inverse();
  edge.robust = true;
  return edge;
}

// The graph from the result's keyframe poses and its accepted candidates:
// sets the corrected poses and each accepted loop's weight.
void solveGraph(LoopClosureResult& result, const LoopClosureConfig& config) {
  std::vector<GraphEdge> edges;
  for (int k = 1; k < static_cast<int>(result.T_odom_lidar.size()); ++k) edges.push_back(odometryEdge(result, k, config));
  std::vector<std::size_t> loops;  // index into candidates of each loop edge
  for (std::size_t c = 0; c < result.candidates.size(); ++c) {
    if (!result.candidates[c].reason.empty()) continue;
    loops.push_back(c);
    edges.push_back(loopEdge(result.candidates[c], config));
  }
  const std::size_t first_loop = edges.size() - loops.size();
  const GraphSolution solution = solveGlobalPoseGraph(result.T_odom_lidar, edges, config.loop_kernel);
  result.solved = solution.solved;
  result.T_odom_lidar_corrected = solution.solved ? solution.poses : result.T_odom_lidar;
  for (std::size_t k = 0; k < loops.size(); ++k)
    result.candidates[loops[k]].graph_weight = solution.edge_weights[first_loop + k];
}

}  // namespace

// A loop must agree with the odometry within the drift the graph allows it
// over the path between the two keyframes (the odometry's own uncertainty,
// as LIO-SAM searches candidates within a radius of the odometry's pose):
// scenes with a symmetry or a repeated room register well in a wrong place.
std::string offByDrift(const Eigen::Isometry3d& offset, double path, const LoopClosureConfig& config) {
  const double sqrt_path = std::sqrt(std::max(path, kMinEdgePath));
  const double max_m = config.odometry_gate_sigmas * config.odometry_sigma_m * sqrt_path;
  const double max_deg = config.odometry_gate_sigmas * config.odometry_sigma_deg * sqrt_path;
  const double off_m = offset.translation().norm();
  const double off_deg = rotationAngle(offset) / kDegree;
  if (off_m <= max_m && off_deg <= max_deg) return "";
  return fmt::format("off the odometry by {:.2f} m, {:.1f} deg (> {:.2f} m, {:.1f} deg)", off_m, off_deg, max_m,
                     max_deg);
}

std::size_t LoopClosureResult::accepted() const {
  return static_cast<std::size_t>(std::count_if(candidates.begin(), candidates.end(),
                                                [](const LoopCandidateRecord& c) { return c.reason.empty(); }));
}

LoopClosure::LoopClosure(const LoopClosureConfig& config, const lidar::RegistrationConfig& registration)
    : config_(config), registration_(registration) {}

bool LoopClosure::addKeyframe(LoopKeyframe keyframe) {
  descriptors_.push_back(scanContextOf(keyframe.points, config_.scan_context));
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
      verifyLoop(keyframes_.back().points,
                 submapAround(keyframes_, found->index, config_.submap_keyframes, static_cast<int>(keyframes_.size()) - 2),
                 found->match.yaw, config_, registration_);
  const LoopKeyframe& from = keyframes_[static_cast<std::size_t>(found->index)];
  record.reason = record.verification.reason.empty()
                      ? offOdometry(from.T_odom_lidar, keyframes_.back().T_odom_lidar,
                                    keyframes_.back().path_length - from.path_length,
                                    record.verification.T_candidate_query, config_)
                      : record.verification.reason;
  const bool accepted = record.reason.empty();
  candidates_.push_back(std::move(record));
  return accepted;
}

LoopClosureResult LoopClosure::solve() const {
  LoopClosureResult result;
  result.candidates = candidates_;
  for (const LoopKeyframe& kf : keyframes_) {
    result.keyframe_times.push_back(kf.t);
    result.path_lengths.push_back(kf.path_length);
    result.T_odom_lidar.push_back(kf.T_odom_lidar);
  }
  solveGraph(result, config_);
  return result;
}

LoopClosureResult regateWithOdometry(const LoopClosureResult& live, const std::vector<Eigen::Isometry3d>& T_odom_lidar,
                                     const std::string& odometry, const LoopClosureConfig& config) {
  LoopClosureResult result = live;
  result.T_odom_lidar = T_odom_lidar;
  result.odometry = odometry;
  for (LoopCandidateRecord& c : result.candidates) {
    c.graph_weight = 0.0;
    if (!c.verified || !c.verification.reason.empty()) continue;
    const auto from = static_cast<std::size_t>(c.candidate), to = static_cast<std::size_t>(c.query);
    c.reason = offOdometry(T_odom_lidar[from], T_odom_lidar[to], result.path_lengths[to] - result.path_lengths[from],
                           c.verification.T_candidate_query, config);
  }
  solveGraph(result, config);
  return result;
}

}  // namespace lvslam::loop
