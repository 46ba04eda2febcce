#include "lvslam/system/online/fused_estimator.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "lvslam/core/error.h"
#include "lvslam/system/online/pose_information.h"

namespace lvslam::system {

namespace {

constexpr double kDegToRad = M_PI / 180.0;

// A drifting frame's (the odometry's, a visual map's) random walk from its
// previous node to the next: isotropic about the camera, growing with the
// root of the path between the camera's two poses in that frame, only along
// directions the pose was `seen` in (the frame slips freely along the
// others), plus `walk` (camera frame) where the frame was not held at all.
// No drift (no path, or drift off) leaves a floor: the frame held, the
// information finite.
Matrix6d driftInformation(const Eigen::Isometry3d& T_frame_previous, const Eigen::Isometry3d& T_frame_camera,
                          const PseudoInverse& seen, double drift_m, double drift_rad,
                          const Matrix6d& walk = Matrix6d::Zero()) {
  constexpr double kRigid = 1e-6;
  const double root_path = std::sqrt((T_frame_previous.inverse() * T_frame_camera).translation().norm());
  const Matrix6d drift =
      isotropicCovariance(std::max(kRigid, drift_m * root_path), std::max(kRigid, drift_rad * root_path)) + walk;
  const Matrix6d Ad_inverse = adjointSE3(T_frame_camera.inverse());
  return Ad_inverse.transpose() * informationOn(seen.range, drift) * Ad_inverse;
}

}  // namespace

FusedEstimator::FusedEstimator(const FusedEstimatorConfig& config)
    : config_(config),
      lidar_gate_(FactorSource::kLidar, {config.motion_accel, config.motion_angular_accel_deg * kDegToRad,
                                         config.gate_accept_after}),
      visual_gate_(FactorSource::kVisual, {config.motion_accel, config.motion_angular_accel_deg * kDegToRad,
                                           config.gate_accept_after}) {
  if (config.history_s >= 0.0 && !(config.history_s > config.window_s))
    throw Error("FusedEstimator", "history_s must exceed window_s (or be negative: the whole run)");
}

FusedEstimator::Candidate FusedEstimator::makeCandidate(PoseFactor factor) const {
  Candidate c;
  c.rank = pseudoInverse(factor.information).rank;
  c.T_world_implied = nodeAt(factor.from).T_world_camera * factor.T_from_to;
  c.factor = std::move(factor);
  return c;
}

int FusedEstimator::addNode(double t, const Eigen::Isometry3d& T, bool fixed) {
  times_.push_back(t);
  nodes_.push_back({T, fixed});
  factors_to_.emplace_back();
  return first_node_ + static_cast<int>(nodes_.size()) - 1;
}

void FusedEstimator::accept(const PoseFactor& factor) {
  factorsTo(factor.to).push_back(first_factor_ + static_cast<int>(factors_.size()));
  factors_.push_back(factor);
}

// The camera node whose time is t (a map's first view is an earlier frame).
std::optional<int> FusedEstimator::cameraNodeAt(double t) const {
  const auto it = std::lower_bound(camera_nodes_.begin(), camera_nodes_.end(), t - 1e-9,
                                   [&](int node, double value) { return timeOf(node) < value; });
  if (it == camera_nodes_.end() || std::abs(timeOf(*it) - t) > 1e-6) return std::nullopt;
  return *it;
}

// Drops what lies more than history_s behind the newest frame. The window
// (window_s < history_s) reads only its own nodes' factors and the nodes
// they start from, all recent: the previous camera, odometry-frame and map
// nodes, and a new map's first view. A map unseen for history_s loses its
// last node and is placed afresh when it is seen again. Stored ids are
// erased in batches of kForgetBatch nodes, so that the vectors shift rarely.
void FusedEstimator::forget(double t_newest) {
  constexpr int kForgetBatch = 2000;
  if (config_.history_s < 0.0) return;
  const double horizon = t_newest - config_.history_s;
  int keep = first_node_;
  while (keep - first_node_ < static_cast<int>(times_.size()) && timeOf(keep) < horizon) ++keep;
  if (last_lidar_) keep = std::min(keep, last_lidar_->first);
  if (keep - first_node_ < kForgetBatch) return;
  for (auto it = last_visual_.begin(); it != last_visual_.end();)
    it = it->second.map_node < keep ? last_visual_.erase(it) : std::next(it);
  int keep_factor = first_factor_ + static_cast<int>(factors_.size());
  for (int id = keep; id < first_node_ + static_cast<int>(nodes_.size()); ++id)
    for (const int f : factorsTo(id)) keep_factor = std::min(keep_factor, f);
  const auto first_camera = std::lower_bound(camera_nodes_.begin(), camera_nodes_.end(), keep);
  auto camera = camera_nodes_.begin();
  for (int id = first_node_; id < keep; ++id) {
    const bool is_camera = camera != first_camera && *camera == id;
    if (is_camera) ++camera;
    retired_nodes_.push_back({timeOf(id), nodeAt(id), is_camera});
  }
  for (int id = first_factor_; id < keep_factor; ++id) retired_factors_.push_back(factorAt(id));
  const auto drop = [](auto& items, int count) { items.erase(items.begin(), items.begin() + count); };
  drop(times_, keep - first_node_);
  drop(nodes_, keep - first_node_);
  drop(factors_to_, keep - first_node_);
  drop(factors_, keep_factor - first_factor_);
  first_node_ = keep;
  first_factor_ = keep_factor;
  camera_nodes_.erase(camera_nodes_.begin(), first_camera);
}

double FusedEstimator::chiSquare(const PoseFactor& factor) const {
  const std::vector<PoseNode> ends{nodeAt(factor.from), nodeAt(factor.to)};
  PoseFactor between = factor;
  between.from = 0;
  between.to = 1;
  return factorChiSquare(between, ends);
}

EstimatorGraph FusedEstimator::takeGraph() {
  EstimatorGraph graph;
  for (const RetiredNode& retired : retired_nodes_) {
    if (retired.camera) graph.camera_nodes.push_back(static_cast<int>(graph.nodes.size()));
    graph.times.push_back(retired.t);
    graph.nodes.push_back(retired.node);
  }
  graph.times.insert(graph.times.end(), times_.begin(), times_.end());
  graph.nodes.insert(graph.nodes.end(), nodes_.begin(), nodes_.end());
  graph.camera_nodes.insert(graph.camera_nodes.end(), camera_nodes_.begin(), camera_nodes_.end());
  graph.factors = std::move(retired_factors_);
  for (const PoseFactor& factor : factors_) graph.factors.push_back(factor);
  retired_nodes_ = {};
  retired_factors_ = {};
  return graph;
}

// The odometry's camera pose, seen through a new odometry-frame node: the
// camera follows the node within the ICP's own covariance (Censi 2007:
// J^T J / sigma^2 at the optimum), and the node follows the last one within
// the drift over the path between (a random walk about the camera). Along a
// direction the registration could not see (Zhang et al. 2016: the ICP keeps
// the prediction there) the odometry dead-reckons, so its frame slips freely
// along it: where the ICP sees that direction again, only the motion from
// there on is trusted, not the position it dead-reckoned to.
std::optional<FusedEstimator::Candidate> FusedEstimator::lidarFactor(int node, const LidarFrameInput& lidar,
                                                                     bool new_start) {
  const double t = timeOf(node);
  if (!last_lidar_) {  // the first LiDAR pose defines the world
    const int odom = addNode(t, Eigen::Isometry3d::Identity(), true);
    last_lidar_ = std::make_pair(odom, lidar);
    return makeCandidate({odom, node, lidar.T_odom_camera, lidar.information, FactorSource::kLidar});
  }
  const int previous_odom = last_lidar_->first;
  const LidarFrameInput previous = last_lidar_->second;
  const int odom = addNode(t, nodeAt(previous_odom).T_world_camera, false);
  last_lidar_ = std::make_pair(odom, lidar);
  const PseudoInverse seen = pseudoInverse(lidar.information);
  if (seen.rank == 0) return std::nullopt;
  if (!new_start) {  // a new start: the odometry jumped and stayed; its frame takes the jump, the output does not
    // A degenerate registration kept some directions at the prediction
    // (Zhang et al. 2016) and went into the map so: scan-to-map no longer
    // holds the odometry to its map, and its error stays, as a frame-to-frame
    // odometry's does. Each new one walks the frame by its own covariance, as
    // weighed by its steps (the step gate's noise scale).
    const bool walks = lidar.degenerate && lidar.registration > last_walk_registration_;
    if (walks) last_walk_registration_ = lidar.registration;
    const Matrix6d walk = walks ? seen.inverse : Matrix6d::Zero();
    accept({previous_odom, odom, Eigen::Isometry3d::Identity(),
            driftInformation(previous.T_odom_camera, lidar.T_odom_camera, seen, config_.lidar_drift_m,
                             config_.lidar_drift_deg * kDegToRad, walk),
            FactorSource::kLidar});
  }
  return makeCandidate({odom, node, lidar.T_odom_camera, lidar.information, FactorSource::kLidar});
}

// The tracker's pose in its map, seen through a new node of the map's frame
// (T_world_map): the camera follows that node within the tracker's own
// covariance, and the node follows the map's previous node within the map's
// drift over the path between, after the map's own corrections since. A new
// map is placed by its first view (an earlier frame) when it has one.
std::optional<FusedEstimator::Candidate> FusedEstimator::visualFactor(int node, const VisualFrameInput& visual,
                                                                      bool use, bool new_start) {
  const auto last = last_visual_.find(visual.map_id);
  if (visual.T_new_old && last != last_visual_.end()) last->second.T_new_old = *visual.T_new_old * last->second.T_new_old;
  if (!use) return std::nullopt;
  const double t = timeOf(node);
  const Matrix6d& information = visual.information;
  const PseudoInverse seen = pseudoInverse(information);
  if (seen.rank == 0) return std::nullopt;
  int map_node = -1;
  if (last != last_visual_.end()) {
    const LastVisual held = last->second;
    const Eigen::Isometry3d T_old_new = held.T_new_old.inverse();
    map_node = addNode(t, nodeAt(held.map_node).T_world_camera * T_old_new, false);
    if (!new_start)
      accept({held.map_node, map_node, T_old_new,
              driftInformation(held.T_new_old * held.T_map_camera, visual.T_map_camera, seen, config_.visual_drift_m,
                               config_.visual_drift_deg * kDegToRad),
              FactorSource::kVisual});
  } else {
    const Eigen::Isometry3d& T_world_camera = nodeAt(node).T_world_camera;
    map_node = addNode(t, T_world_camera * visual.T_map_camera.inverse(), false);
    const std::optional<int> first =
        visual.initial_view ? cameraNodeAt(visual.initial_view->t) : std::nullopt;
    if (first) {  // measured from the first view's node: the map's frame as that view places it
      const Eigen::Isometry3d T_first_map = visual.initial_view->T_world_frame.inverse();
      nodeAt(map_node).T_world_camera =
          nodeAt(*first).T_world_camera * T_first_map;
      // The factor map -> first view, turned round to end at the map's node:
      // its residual is -Ad(T_map_first) times the original one.
      const Matrix6d Ad = adjointSE3(T_first_map);
      accept({*first, map_node, T_first_map, Ad.transpose() * information * Ad, FactorSource::kVisual});
    }
  }
  last_visual_[visual.map_id] = {map_node, visual.T_map_camera, Eigen::Isometry3d::Identity()};
  return makeCandidate({map_node, node, visual.T_map_camera, information, FactorSource::kVisual});
}

// Constant velocity from the last two nodes; the platform's acceleration
// over dt moves the pose by about a dt^2.
FusedEstimator::Candidate FusedEstimator::motionFactor(int node, double t) const {
  const std::size_t k = camera_nodes_.size() - 1;  // this frame's; k >= 1
  const int previous = camera_nodes_[k - 1];
  const double dt = t - timeOf(previous);
  Eigen::Isometry3d T_step = Eigen::Isometry3d::Identity();
  double sigma_m = config_.motion_accel * dt * dt, sigma_rad = config_.motion_angular_accel_deg * kDegToRad * dt * dt;
  if (k >= 2) {
    const int before = camera_nodes_[k - 2];
    const double dt_before = timeOf(previous) - timeOf(before);
    const Eigen::Isometry3d T_last = nodeAt(before).T_world_camera.inverse() *
                                     nodeAt(previous).T_world_camera;
    if (dt_before > 0) T_step = expSE3(logSE3(T_last) * (dt / dt_before));
  } else {
    sigma_m = 2.0 * dt;  // no velocity yet: anything a walking robot does
    sigma_rad = 90.0 * kDegToRad * dt;
  }
  const Matrix6d information = isotropicCovariance(sigma_m, sigma_rad).inverse();
  return makeCandidate({previous, node, T_step, information, FactorSource::kMotion});
}

std::optional<Matrix6d> FusedEstimator::solveWindow(int newest, int of) {
  const double start = timeOf(newest) - config_.window_s;
  int first = newest;
  while (first > first_node_ && timeOf(first - 1) >= start) --first;
  // The window's nodes free, every older node its factors reach held at its
  // last estimate.
  std::vector<const PoseFactor*> factors;
  for (int node = first; node <= newest; ++node)
    for (const int f : factorsTo(node)) factors.push_back(&factorAt(f));
  const PoseGraphSolveConfig solve{config_.huber_delta, config_.max_iterations, true};
  NodeCovariance covariance{of, std::nullopt};
  if (!solveSubgraph(first, newest + 1, factors, [this](int id) -> PoseNode& { return nodeAt(id); }, solve,
                     &covariance))
    return std::nullopt;
  return covariance.covariance;
}

FusedFrameOutput FusedEstimator::add(double t, const std::optional<LidarFrameInput>& lidar,
                                     const std::optional<VisualFrameInput>& visual) {
  FusedFrameOutput out;
  if (camera_nodes_.empty() && !lidar) return out;  // the world is the odometry frame: wait for its first pose
  const Eigen::Isometry3d guess = camera_nodes_.empty() ? lidar->T_odom_camera
                                                        : nodeAt(camera_nodes_.back()).T_world_camera;
  // The first camera pose is the LiDAR's: it fixes the world (a direction
  // the LiDAR cannot see at the start would otherwise float).
  const int node = addNode(t, guess, camera_nodes_.empty());
  camera_nodes_.push_back(node);
  std::optional<Candidate> lidar_candidate, visual_candidate;
  if (lidar) {
    const std::optional<GateEvent> jump =
        lidar_gate_.check(t, lidar->T_odom_camera, lidar->information, !visual.has_value());
    LidarFrameInput weighed = *lidar;
    weighed.information /= lidar_gate_.noiseScale();
    if (jump) out.gated.push_back(*jump);
    else lidar_candidate = lidarFactor(node, weighed, lidar_gate_.restarted());
  }
  if (visual) {
    if (visual->map_id != visual_map_) visual_gate_.reset();
    visual_map_ = visual->map_id;
    if (visual->T_new_old) visual_gate_.moveHistory(*visual->T_new_old);
    const double s = config_.visual_pixel_sigma;
    const std::optional<GateEvent> jump =
        visual_gate_.check(t, visual->T_map_camera, visual->information / (s * s), !lidar.has_value());
    VisualFrameInput weighed = *visual;  // at the estimator's pixel sigma, times the gate's noise scale
    weighed.information = visual->information / visual_gate_.noiseScale() / (s * s);
    if (jump) out.gated.push_back(*jump);
    visual_candidate = visualFactor(node, weighed, !jump, visual_gate_.restarted());
  }
  std::optional<Candidate> motion;
  if (camera_nodes_.size() >= 2) motion = motionFactor(node, t);
  // Start from the best single guess: the LiDAR's, else vision's, else the motion model's.
  nodeAt(node).T_world_camera =
      lidar_candidate ? lidar_candidate->T_world_implied
                      : visual_candidate ? visual_candidate->T_world_implied
                                         : motion ? motion->T_world_implied : guess;
  if (motion) accept(motion->factor);
  if (lidar_candidate) accept(lidar_candidate->factor);
  if (visual_candidate) accept(visual_candidate->factor);
  out.covariance = solveWindow(first_node_ + static_cast<int>(nodes_.size()) - 1, node);
  out.T_world_camera = nodeAt(node).T_world_camera;
  out.camera_node = node;
  out.lidar_noise_scale = lidar_gate_.noiseScale();
  out.visual_noise_scale = visual_gate_.noiseScale();
  out.lidar_used = lidar_candidate.has_value();
  out.visual_used = visual_candidate.has_value();
  if (visual_candidate)
    out.visual_chi_square_per_dof =
        chiSquare(visual_candidate->factor) / std::max(1, visual_candidate->rank);
  forget(t);
  return out;
}

void FusedEstimator::improveLidar(int camera_node, const LidarFrameInput& lidar) {
  if (camera_node < first_node_ || camera_node >= first_node_ + static_cast<int>(factors_to_.size())) return;
  for (const int f : factorsTo(camera_node)) {
    PoseFactor& factor = factorAt(f);
    if (factor.source != FactorSource::kLidar) continue;
    factor.T_from_to = lidar.T_odom_camera;
    factor.information = lidar.information / lidar_gate_.noiseScale();
    if (last_lidar_ && last_lidar_->first == factor.from) last_lidar_->second = lidar;
  }
}

}  // namespace lvslam::system
