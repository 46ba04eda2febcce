#pragma once
// The LiDAR subsystem's odometry (MULLS-style), split in two steps so that the
// fusion framework can act between them:
//   prepare(scan)            deskew (constant velocity), preprocess, classify
//   currentFrame(), recentFrames(), currentFeaturesAt(t)      what fusion reads
//   setLinearDirections(...)  the paper's d_v_mean on a group of linear points
//   registerScan()           multi-metric ICP, velocity refinement, map update
// process(scan) does both steps with nothing in between.
#include <cstddef>
#include <deque>
#include <optional>
#include <span>
#include <vector>

#include "lvslam/core/lidar_scan.h"
#include "lvslam/core/se3.h"
#include "lvslam/lidar/adaptive_threshold.h"
#include "lvslam/lidar/feature_point.h"
#include "lvslam/lidar/lidar_config.h"
#include "lvslam/lidar/local_map.h"
#include "lvslam/lidar/multi_metric_icp.h"
#include "lvslam/lidar/velocity_filter.h"

namespace lvslam::lidar {

enum class OdometryStatus {
  kInitialized,  // first usable scan: it starts the map at the identity
  kTracking,     // registered
  kDegenerate,   // registered, but some directions kept the constant-velocity prediction
  kLost,         // too few features or correspondences, or a wild correction: prediction kept, map untouched
  kRestarted,    // lost restart_after_lost times in a row: the local map restarts from this scan, predicted
  kRejected,     // time stamp not after the previous scan's: ignored entirely
};
const char* statusName(OdometryStatus status);

struct OdometryResult {
  OdometryStatus status = OdometryStatus::kLost;
  double timestamp = 0.0;
  Eigen::Isometry3d T_world_lidar = Eigen::Isometry3d::Identity();
  std::size_t features = 0;
  std::size_t correspondences = 0;
  int iterations = 0;
  double localizability = 0.0;  // IcpResult::localizability
  // Information of T_world_lidar against the local map (IcpResult::information);
  // zero unless the scan was registered (tracking or degenerate).
  Matrix6d information = Matrix6d::Zero();
};

class LidarOdometry {
 public:
  explicit LidarOdometry(const LidarOdometryConfig& config);

  void prepare(const LidarScan& scan);
  OdometryResult registerScan();
  OdometryResult process(const LidarScan& scan);

  // The prepared scan: features in the LiDAR frame at its time stamp, with
  // T_world_lidar the prediction until registerScan() replaces it.
  const FeatureFrame& currentFrame() const { return current_; }
  // The last `recent_frames` registered frames, oldest first.
  const std::deque<FeatureFrame>& recentFrames() const { return recent_; }
  // The prepared scan's features moved (rigidly, constant velocity) to the
  // LiDAR frame at absolute time t, e.g. a camera time.
  std::vector<FeaturePoint> currentFeaturesAt(double t) const;
  // Pose of the LiDAR at time t by the current motion estimate (constant
  // velocity around the current frame).
  Eigen::Isometry3d poseAt(double t) const;
  // What the constant velocity adds to poseAt(t)'s covariance (body frame,
  // (rho, phi)): the velocity's own covariance over the time from the
  // registered middle of the sweep, squared.
  Matrix6d motionCovarianceAt(double t) const;

  // Gives the linear (pillar / beam) points named by ids, of the current or a
  // recent frame, the direction (world frame) and marks them refined; the
  // local map's copies follow. Ids of other classes or unknown ids are
  // skipped. Returns how many points changed.
  std::size_t setLinearDirections(std::span<const FeatureId> ids, const Eigen::Vector3d& direction_world);

  const LocalMap& localMap() const { return map_; }
  const Vector6d& velocity() const { return motion_.velocity; }  // body twist per second

 private:
  // information: the registration's, which weighs its step against the
  // predicted velocity (zero: no registration, the step is taken as is).
  OdometryResult finish(OdometryStatus status, const Eigen::Isometry3d& T,
                        const Matrix6d& information = Matrix6d::Zero());
  static void redeskew(FeatureFrame& frame, const Vector6d& old_velocity, const Vector6d& new_velocity);
  IcpResult bootstrapSecondFrame(const IcpResult& first_try, double threshold);
  double typicalInlierRatio() const;  // mean of recent_inlier_ratios_, 1 without any
  FeatureFrame* frameWithSeq(std::uint32_t seq);

  LidarOdometryConfig config_;
  LocalMap map_;
  AdaptiveThreshold threshold_;
  FeatureFrame current_;
  std::deque<FeatureFrame> recent_;
  bool prepared_ = false;
  bool rejected_ = false;
  bool time_jump_ = false;
  bool has_previous_ = false;
  int lost_in_row_ = 0;  // registrations lost since the last good one
  // Inlier ratios of the last good registrations: how much of a scan this map
  // can match at all (a young map, or far and sparse outdoor features, match
  // less of a rightly registered scan than a dense room map does).
  static constexpr std::size_t kInlierRatioHistory = 5;
  std::deque<double> recent_inlier_ratios_;
  // Registration estimates the pose at the middle of the sweep, where an error
  // of the deskew velocity averages out (kiss-icp's mid-pose); velocities come
  // from consecutive mid-sweep poses, so deskew errors cannot feed back.
  double mid_offset_ = 0.0;  // middle of the current sweep minus its time stamp
  double previous_mid_time_ = 0.0;
  Eigen::Isometry3d T_world_previous_mid_ = Eigen::Isometry3d::Identity();
  double previous_time_ = 0.0;
  Eigen::Isometry3d T_world_previous_ = Eigen::Isometry3d::Identity();  // at the previous time stamp
  VelocityEstimate motion_;  // predicts and deskews the next scan
  std::uint32_t next_seq_ = 0;
};

}  // namespace lvslam::lidar
