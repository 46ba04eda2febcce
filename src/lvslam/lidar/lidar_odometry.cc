#include "lvslam/lidar/lidar_odometry.h"

#include <algorithm>
#include <cmath>

#include "lvslam/core/error.h"
#include "lvslam/lidar/deskew.h"
#include "lvslam/lidar/feature_extraction.h"
#include "lvslam/lidar/preprocess.h"

namespace lvslam::lidar {

namespace {

// Middle of the sweep relative to the time stamp (0 without per-point times).
double midOffset(const std::vector<TimedPoint>& points) {
  if (points.empty()) return 0.0;
  const auto [lo, hi] = std::minmax_element(points.begin(), points.end(),
                                            [](const TimedPoint& a, const TimedPoint& b) { return a.time < b.time; });
  return 0.5 * (static_cast<double>(lo->time) + static_cast<double>(hi->time));
}

}  // namespace

const char* statusName(OdometryStatus status) {
  switch (status) {
    case OdometryStatus::kInitialized: return "initialized";
    case OdometryStatus::kTracking: return "tracking";
    case OdometryStatus::kDegenerate: return "degenerate";
    case OdometryStatus::kLost: return "lost";
    case OdometryStatus::kRestarted: return "restarted";
    case OdometryStatus::kRejected: return "rejected";
  }
  return "unknown";
}

LidarOdometry::LidarOdometry(const LidarOdometryConfig& config)
    : config_(config),
      map_(config.local_map),
      threshold_(config.registration.initial_threshold, config.registration.min_threshold,
                 config.registration.max_threshold, config.preprocess.max_range) {
  validate(config_, "LidarOdometryConfig");
}

void LidarOdometry::prepare(const LidarScan& scan) {
  prepared_ = true;
  rejected_ = false;
  current_ = FeatureFrame{};
  current_.timestamp = scan.timestamp;
  if (!std::isfinite(scan.timestamp) || (has_previous_ && scan.timestamp <= previous_time_)) {
    rejected_ = true;
    current_.T_world_lidar = T_world_previous_;
    return;
  }
  current_.seq = next_seq_++;
  // After a gap in time the velocity says nothing about the motion since.
  time_jump_ = has_previous_ && scan.timestamp - previous_time_ > config_.max_time_gap;
  if (time_jump_) motion_ = VelocityEstimate{};
  std::vector<TimedPoint> points = cropAndDownsample(scan, config_.preprocess, config_.features.neighbour_radius);
  const bool deskew = config_.deskew && scan.has_time;
  mid_offset_ = deskew ? midOffset(points) : 0.0;
  const Eigen::Isometry3d T_world_mid =
      T_world_previous_mid_ * motionOver(motion_.velocity, scan.timestamp + mid_offset_ - previous_mid_time_);
  current_.T_world_lidar = has_previous_ ? T_world_mid * motionOver(motion_.velocity, -mid_offset_) : T_world_previous_;
  if (deskew) deskewToReference(points, motion_.velocity);
  current_.deskew = deskew ? DeskewState::kPredicted : DeskewState::kRaw;
  current_.points = extractFeatures(points, config_.ground, config_.features);
}

OdometryResult LidarOdometry::process(const LidarScan& scan) {
  prepare(scan);
  return registerScan();
}

OdometryResult LidarOdometry::registerScan() {
  if (!prepared_ || rejected_) {
    prepared_ = false;
    OdometryResult result;
    result.status = OdometryStatus::kRejected;
    result.timestamp = current_.timestamp;
    result.T_world_lidar = T_world_previous_;
    return result;
  }
  prepared_ = false;
  const RegistrationConfig& reg = config_.registration;
  const Eigen::Isometry3d T_pred = current_.T_world_lidar;
  if (current_.points.size() < reg.min_correspondences) return finish(OdometryStatus::kLost, T_pred);
  if (map_.empty()) return finish(OdometryStatus::kInitialized, T_pred);
  const double threshold = time_jump_ ? reg.max_threshold : threshold_.threshold();
  IcpResult icp = registerMultiMetric(current_.points, map_, T_pred, threshold, reg);
  if (recent_.size() == 1 && recent_.front().deskew == DeskewState::kPredicted && !time_jump_ &&
      icp.correspondences >= reg.min_correspondences)
    icp = bootstrapSecondFrame(icp, threshold);
  const Eigen::Isometry3d correction = T_pred.inverse() * icp.T_world_lidar;
  const bool wild = correction.translation().norm() > reg.max_correction_translation ||
                    rotationAngle(correction) > reg.max_correction_rotation_deg * M_PI / 180.0;
  OdometryResult result;
  const double inlier_ratio =
      static_cast<double>(icp.correspondences) / static_cast<double>(current_.points.size());
  const bool few_inliers = inlier_ratio < reg.min_inlier_ratio * typicalInlierRatio();
  if (icp.correspondences < reg.min_correspondences || few_inliers || wild ||
      !icp.T_world_lidar.matrix().allFinite()) {
    if (reg.restart_after_lost > 0 && ++lost_in_row_ >= reg.restart_after_lost) {
      // The map no longer matches what the scans see (or never did): the
      // prediction carries the pose over, the scan starts a new map.
      lost_in_row_ = 0;
      map_ = LocalMap(config_.local_map);
      recent_.clear();
      recent_inlier_ratios_.clear();
      result = finish(OdometryStatus::kRestarted, T_pred);
    } else {
      result = finish(OdometryStatus::kLost, T_pred);
    }
  } else {
    lost_in_row_ = 0;
    recent_inlier_ratios_.push_back(inlier_ratio);
    if (recent_inlier_ratios_.size() > kInlierRatioHistory) recent_inlier_ratios_.pop_front();
    if (!time_jump_) threshold_.update(correction);
    result = finish(icp.degenerate ? OdometryStatus::kDegenerate : OdometryStatus::kTracking, icp.T_world_lidar,
                    icp.information);
    result.information = icp.information;
  }
  result.correspondences = icp.correspondences;
  result.iterations = icp.iterations;
  result.localizability = icp.localizability;
  return result;
}

OdometryResult LidarOdometry::finish(OdometryStatus status, const Eigen::Isometry3d& T_registered,
                                     const Matrix6d& information) {
  const bool registered = status != OdometryStatus::kLost;
  const double mid_time = current_.timestamp + mid_offset_;
  const Eigen::Isometry3d T_world_mid = T_registered * motionOver(motion_.velocity, mid_offset_);
  if (registered && has_previous_ && !time_jump_) {
    const Vector6d step = velocityBetween(T_world_previous_mid_, previous_mid_time_, T_world_mid, mid_time);
    VelocityEstimate next{step, motion_.covariance};
    if (!information.isZero())  // a registration: weighed against the prediction
      next = updateVelocity(motion_, step, information, mid_time - previous_mid_time_,
                            {config_.motion_accel, config_.motion_angular_accel_deg * M_PI / 180.0});
    if (current_.deskew != DeskewState::kRaw) {
      redeskew(current_, motion_.velocity, next.velocity);
      current_.deskew = DeskewState::kRefined;
    }
    motion_ = next;
  }
  current_.T_world_lidar = T_world_mid * motionOver(motion_.velocity, -mid_offset_);
  if (registered) {
    map_.update(current_);
    recent_.push_back(current_);
    while (recent_.size() > static_cast<std::size_t>(config_.recent_frames)) recent_.pop_front();
  }
  T_world_previous_mid_ = T_world_mid;
  previous_mid_time_ = mid_time;
  T_world_previous_ = current_.T_world_lidar;
  previous_time_ = current_.timestamp;
  has_previous_ = true;
  OdometryResult result;
  result.status = status;
  result.timestamp = current_.timestamp;
  result.T_world_lidar = current_.T_world_lidar;
  result.features = current_.points.size();
  return result;
}

// Registration refined the velocity: compensate the sweep again with it.
void LidarOdometry::redeskew(FeatureFrame& frame, const Vector6d& old_velocity, const Vector6d& new_velocity) {
  for (FeaturePoint& fp : frame.points) {
    const Eigen::Isometry3d T_new_old = motionOver(new_velocity, fp.time) * motionOver(old_velocity, fp.time).inverse();
    fp.p = (T_new_old * fp.p.cast<double>()).cast<float>();
    fp.direction = (T_new_old.linear() * fp.direction.cast<double>()).normalized().cast<float>();
  }
}

double LidarOdometry::typicalInlierRatio() const {
  if (recent_inlier_ratios_.empty()) return 1.0;
  double sum = 0.0;
  for (const double r : recent_inlier_ratios_) sum += r;
  return std::min(1.0, sum / static_cast<double>(recent_inlier_ratios_.size()));
}

// The first frame went into the map deskewed without a velocity; the second
// registration gives one: compensate the first frame with it, rebuild the map
// and register again, so the whole run does not inherit a skewed map.
IcpResult LidarOdometry::bootstrapSecondFrame(const IcpResult& first_try, double threshold) {
  const Eigen::Isometry3d T_world_mid = first_try.T_world_lidar * motionOver(motion_.velocity, mid_offset_);
  const Vector6d v =
      velocityBetween(T_world_previous_mid_, previous_mid_time_, T_world_mid, current_.timestamp + mid_offset_);
  FeatureFrame& first = recent_.front();
  redeskew(first, Vector6d::Zero(), v);
  first.deskew = DeskewState::kRefined;
  // The first frame's time stamp pose is the world origin; its middle moved on.
  T_world_previous_mid_ = first.T_world_lidar * motionOver(v, previous_mid_time_ - first.timestamp);
  redeskew(current_, motion_.velocity, v);
  motion_.velocity = v;
  map_ = LocalMap(config_.local_map);
  map_.update(first);
  return registerMultiMetric(current_.points, map_, first_try.T_world_lidar, threshold, config_.registration);
}

std::vector<FeaturePoint> LidarOdometry::currentFeaturesAt(double t) const {
  const Eigen::Isometry3d T_at_ref = motionOver(motion_.velocity, t - current_.timestamp).inverse();
  std::vector<FeaturePoint> moved = current_.points;
  for (FeaturePoint& fp : moved) {
    fp.p = (T_at_ref * fp.p.cast<double>()).cast<float>();
    fp.direction = (T_at_ref.linear() * fp.direction.cast<double>()).cast<float>();
    fp.time -= static_cast<float>(t - current_.timestamp);
  }
  return moved;
}

Eigen::Isometry3d LidarOdometry::poseAt(double t) const {
  return current_.T_world_lidar * motionOver(motion_.velocity, t - current_.timestamp);
}

Matrix6d LidarOdometry::motionCovarianceAt(double t) const {
  const double dt = t - (current_.timestamp + mid_offset_);
  return dt * dt * motion_.covariance;
}

std::size_t LidarOdometry::setLinearDirections(std::span<const FeatureId> ids, const Eigen::Vector3d& direction_world) {
  if (!direction_world.allFinite() || direction_world.norm() < 1e-9)
    throw Error("LidarOdometry::setLinearDirections", "the direction must be finite and non-zero");
  const Eigen::Vector3d d = direction_world.normalized();
  std::vector<FeatureId> map_ids;
  std::vector<Eigen::Vector3f> map_positions;
  std::size_t changed = 0;
  for (const FeatureId id : ids) {
    bool changed_id = false;
    auto apply = [&](FeatureFrame& frame, bool in_map) {
      if (frame.points.empty() || frame.seq != frameOf(id) || indexOf(id) >= frame.points.size()) return;
      FeaturePoint& fp = frame.points[indexOf(id)];
      if (!isLinear(fp.cls)) return;
      fp.direction = (frame.T_world_lidar.linear().transpose() * d).cast<float>();
      fp.refined = true;
      if (in_map && !changed_id) {
        map_ids.push_back(id);
        map_positions.push_back((frame.T_world_lidar * fp.p.cast<double>()).cast<float>());
      }
      changed_id = true;
    };
    if (prepared_ && !rejected_) apply(current_, false);
    for (FeatureFrame& frame : recent_) apply(frame, true);
    changed += changed_id ? 1 : 0;
  }
  map_.setDirections(map_ids, map_positions, d.cast<float>());
  return changed;
}

}  // namespace lvslam::lidar
