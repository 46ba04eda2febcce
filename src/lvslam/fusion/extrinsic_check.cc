#include "lvslam/fusion/extrinsic_check.h"

#include <array>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>
#include <fmt/format.h>

#include "lvslam/core/se3.h"

namespace lvslam::fusion {

namespace {

constexpr double kDegToRad = M_PI / 180.0;
constexpr double kRadToDeg = 180.0 / M_PI;
constexpr int kIterationsPerGate = 3;
// The gate shrinks as the fit converges, from twice the fusion's own
// association gate (a misalignment that large still finds its edges) to half of it.
constexpr std::array<double, 3> kGateScales = {2.0, 1.0, 0.5};

// Whether bearing q (near the arc's great circle) lies between the arc's ends.
bool withinArc(const ExtrinsicCheck::Arc& arc, const Eigen::Vector3d& q) {
  return arc.a.cross(q).dot(arc.n) >= 0.0 && q.cross(arc.b).dot(arc.n) >= 0.0;
}

// Each LiDAR edge with the arc nearest to it after rotation R, when within the
// gate and when the edge's direction lies in the arc's plane (an edge that
// only crosses the image line says nothing about its offset). Accumulates
// the Gauss-Newton system of the residual r = n . (R q), the sine of the
// bearing's angle off the great circle; r(delta) = r + delta . (q x n).
std::size_t accumulate(const ExtrinsicCheck::Frame& frame, const Eigen::Matrix3d& R, double gate,
                       double direction_tolerance, Eigen::Matrix3d& H, Eigen::Vector3d& g) {
  const double max_offset = std::sin(gate), max_off_plane = std::sin(direction_tolerance);
  std::size_t used = 0;
  for (const ExtrinsicCheck::Edge& edge : frame.edges) {
    const Eigen::Vector3d q = R * edge.bearing, d = R * edge.direction;
    const ExtrinsicCheck::Arc* best = nullptr;
    double best_offset = max_offset;
    for (const ExtrinsicCheck::Arc& arc : frame.arcs) {
      const double offset = std::abs(arc.n.dot(q));
      if (offset >= best_offset || std::abs(arc.n.dot(d)) > max_off_plane || !withinArc(arc, q)) continue;
      best = &arc;
      best_offset = offset;
    }
    if (!best) continue;
    const Eigen::Vector3d J = q.cross(best->n);
    H += J * J.transpose();
    g += J * best->n.dot(q);
    ++used;
  }
  return used;
}

}  // namespace

double studentT999(int dof) {
  static constexpr std::array<double, 31> kTable = {
      std::numeric_limits<double>::infinity(), 318.31, 22.327, 10.215, 7.173, 5.893, 5.208, 4.785, 4.501, 4.297,
      4.144, 4.025, 3.930, 3.852, 3.787, 3.733, 3.686, 3.646, 3.610, 3.579, 3.552, 3.527, 3.505, 3.485, 3.467, 3.450,
      3.435, 3.421, 3.408, 3.396, 3.385};
  if (dof < 1) return std::numeric_limits<double>::infinity();
  if (dof < static_cast<int>(kTable.size())) return kTable[static_cast<std::size_t>(dof)];
  // Cornish-Fisher expansion around the normal quantile (Abramowitz & Stegun 26.7.5).
  const double z = 3.090232, n = static_cast<double>(dof);
  const double z3 = z * z * z, z5 = z3 * z * z, z7 = z5 * z * z;
  return z + (z3 + z) / (4.0 * n) + (5.0 * z5 + 16.0 * z3 + 3.0 * z) / (96.0 * n * n) +
         (3.0 * z7 + 19.0 * z5 + 17.0 * z3 - 15.0 * z) / (384.0 * n * n * n);
}

ExtrinsicCheck::ExtrinsicCheck(const PinholeCamera& camera, const FusionConfig& config)
    : camera_(camera), config_(config) {}

std::optional<ExtrinsicVerdict> ExtrinsicCheck::addFrame(std::size_t scan_serial, double t_camera,
                                                         const std::vector<SphereFeature>& features,
                                                         const std::vector<ImageSegment>& segments) {
  const std::size_t per_block = static_cast<std::size_t>(std::max(1, config_.accumulated_scans));
  if (scan_serial < per_block) return std::nullopt;  // the accumulation is not full yet
  const std::size_t block = scan_serial / per_block;
  std::optional<ExtrinsicVerdict> verdict;
  if (!window_.empty() && block >= window_block_ + kBlocksPerWindow) verdict = closeWindow();
  if (window_.empty()) window_block_ = block;
  last_block_ = block;

  Frame frame;
  frame.t = t_camera;
  for (const ImageSegment& s : segments) {
    if (!(s.length() >= config_.min_segment_length_px)) continue;
    const Eigen::Vector3d a = camera_.unproject(s.start).normalized(), b = camera_.unproject(s.end).normalized();
    const Eigen::Vector3d n = a.cross(b);
    if (!n.allFinite() || n.norm() < 1e-9) continue;
    frame.arcs.push_back({a, b, n.normalized()});
  }
  for (const SphereFeature& f : features) {
    if (f.shape != FeatureShape::kLinear || !f.p_camera.allFinite() || !f.direction_camera.allFinite() ||
        f.direction_camera.norm() < 1e-9)
      continue;
    const auto px = camera_.project(f.p_camera);
    if (!px || !camera_.inImage(*px)) continue;
    frame.edges.push_back({f.p_camera.normalized(), f.direction_camera.normalized()});
  }
  if (!frame.arcs.empty() && !frame.edges.empty()) window_.push_back(std::move(frame));
  return verdict;
}

std::optional<Eigen::Vector3d> ExtrinsicCheck::fitRotation(const std::vector<Frame>& frames,
                                                           std::size_t* associations) const {
  const double gate0 = config_.max_neighbour_angle_deg * kDegToRad;
  const double cluster = config_.cluster_angle_deg * kDegToRad;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  std::size_t used = 0;
  for (const double scale : kGateScales) {
    const double gate = scale * gate0;
    for (int it = 0; it < kIterationsPerGate; ++it) {
      Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
      Eigen::Vector3d g = Eigen::Vector3d::Zero();
      used = 0;
      for (const Frame& f : frames) used += accumulate(f, R, gate, cluster + gate, H, g);
      const Eigen::LDLT<Eigen::Matrix3d> ldlt(H);
      // Three independent directions at least, else a direction is free.
      if (used < 3 || ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 1e-9 * H.trace()))
        return std::nullopt;
      Eigen::Vector3d step = -ldlt.solve(g);
      if (!step.allFinite()) return std::nullopt;
      if (step.norm() > gate) step *= gate / step.norm();  // no jump past the associations it came from
      R = expSO3(step) * R;
    }
  }
  if (associations) *associations = used;
  return logSO3(R);
}

std::optional<ExtrinsicVerdict> ExtrinsicCheck::finish() {
  // A window cut short by the end has fewer frames than the others and
  // would count as much in the mean: only a whole one is closed.
  if (window_.empty() || last_block_ + 1 < window_block_ + kBlocksPerWindow) return std::nullopt;
  return closeWindow();
}

ExtrinsicVerdict ExtrinsicCheck::closeWindow() {
  ExtrinsicVerdict v;
  v.t_first = window_.front().t;
  v.t_last = window_.back().t;
  v.frames = static_cast<int>(window_.size());
  v.sigma_deg = std::numeric_limits<double>::infinity();
  const std::optional<Eigen::Vector3d> rotation = fitRotation(window_, &v.associations);
  window_.clear();
  if (rotation) {
    v.window_rotation = *rotation;
    window_rotations_.push_back(*rotation);
    if (window_rotations_.size() > static_cast<std::size_t>(kMaxWindows)) window_rotations_.erase(window_rotations_.begin());
  }
  const int n = static_cast<int>(window_rotations_.size());
  v.windows = n;
  if (n == 0) return v;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& w : window_rotations_) mean += w;
  mean /= n;
  v.rotation = mean;
  v.misalignment_deg = mean.norm() * kRadToDeg;
  if (n < kMinWindows || !(mean.norm() > 0.0)) return v;
  // One-sided t test of |mean| > tolerance along the mean's direction, with
  // the windows' sample variance there.
  const Eigen::Vector3d u = mean.normalized();
  double ss = 0.0;
  for (const Eigen::Vector3d& w : window_rotations_) ss += std::pow(u.dot(w - mean), 2);
  v.sigma_deg = std::sqrt(ss / (n - 1) / n) * kRadToDeg;
  v.misaligned = v.misalignment_deg - kToleranceDeg > studentT999(n - 1) * v.sigma_deg;
  return v;
}

std::string extrinsicWarning(const ExtrinsicVerdict& v, const std::string& where) {
  return fmt::format("{}: LiDAR edges and image edges do not line up: the LiDAR features meet the image edges only "
                     "turned by {:.1f} deg (standard error {:.2f} deg over {} windows of frames up to t = {:.3f}); "
                     "the extrinsic rotation is likely wrong by about that much",
                     where.empty() ? std::string("T_camera_lidar") : where, v.misalignment_deg, v.sigma_deg,
                     v.windows, v.t_last);
}

}  // namespace lvslam::fusion
