// Odometry on short synthetic drives: accuracy against the exact poses, and
// the bad-input cases (empty, NaN, tiny, degenerate, gaps, time going back).
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "lidar/synthetic_lidar.h"
#include "lvslam/lidar/lidar_odometry.h"

namespace lvslam::lidar {
namespace {

using testing::castScan;
using testing::drivePose;
using testing::structuredRoom;
using testing::SyntheticSensor;

struct DriveErrors {
  double max_translation = 0.0;
  double max_rotation_deg = 0.0;
};

// Runs the odometry over scans at the given start times and compares
// T_world_lidar with the truth relative to the first scan's true pose.
DriveErrors runDrive(LidarOdometry& odometry, const std::vector<double>& times, double noise,
                     std::vector<OdometryStatus>* statuses = nullptr) {
  const auto scene = structuredRoom();
  SyntheticSensor sensor;
  sensor.range_noise = noise;
  std::mt19937 rng(7);
  DriveErrors errors;
  const Eigen::Isometry3d T_first_inv = drivePose(times.front()).inverse();
  for (const double t : times) {
    const OdometryResult result = odometry.process(castScan(scene, drivePose, t, sensor, &rng));
    if (statuses) statuses->push_back(result.status);
    const Eigen::Isometry3d error = (T_first_inv * drivePose(t)).inverse() * result.T_world_lidar;
    errors.max_translation = std::max(errors.max_translation, error.translation().norm());
    errors.max_rotation_deg = std::max(errors.max_rotation_deg, rotationAngle(error) * 180.0 / M_PI);
  }
  return errors;
}

std::vector<double> scanTimes(int count, double period = 0.1) {
  std::vector<double> times;
  for (int i = 0; i < count; ++i) times.push_back(i * period);
  return times;
}

TEST(LidarOdometry, FollowsASimulatedDriveWithinCentimetres) {
  LidarOdometry odometry{LidarOdometryConfig{}};
  std::vector<OdometryStatus> statuses;
  // 4 s, ~5 m of path and ~50 deg of turning; 1 cm range noise.
  const DriveErrors errors = runDrive(odometry, scanTimes(40), 0.01, &statuses);
  EXPECT_EQ(statuses.front(), OdometryStatus::kInitialized);
  for (std::size_t i = 1; i < statuses.size(); ++i) EXPECT_EQ(statuses[i], OdometryStatus::kTracking) << i;
  EXPECT_LT(errors.max_translation, 0.04);
  EXPECT_LT(errors.max_rotation_deg, 0.3);
}

TEST(LidarOdometry, ASkippedScanIsBridgedByTheConstantVelocity) {
  LidarOdometry odometry{LidarOdometryConfig{}};
  std::vector<double> times = scanTimes(20);
  times.erase(times.begin() + 10);  // 0.2 s between two scans
  std::vector<OdometryStatus> statuses;
  const DriveErrors errors = runDrive(odometry, times, 0.01, &statuses);
  for (std::size_t i = 1; i < statuses.size(); ++i) EXPECT_EQ(statuses[i], OdometryStatus::kTracking) << i;
  EXPECT_LT(errors.max_translation, 0.04);
  EXPECT_LT(errors.max_rotation_deg, 0.3);
}

// Feeds a few good scans so that the odometry has a velocity, then one bad one.
struct AfterGoodScans {
  LidarOdometry odometry{LidarOdometryConfig{}};
  Eigen::Isometry3d predicted;
  AfterGoodScans() {
    for (const double t : scanTimes(5)) odometry.process(castScan(structuredRoom(), drivePose, t, SyntheticSensor{}));
    predicted = odometry.poseAt(0.5);
  }
};

TEST(LidarOdometry, EmptyTinyAndNanScansAreLostAndKeepThePrediction) {
  LidarScan nan_scan;
  nan_scan.has_time = true;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int i = 0; i < 1000; ++i) nan_scan.points.push_back({Eigen::Vector3f(nan, nan, nan), 0.0f, 0.0f, 0});
  LidarScan tiny;
  for (int i = 0; i < 5; ++i) tiny.points.push_back({Eigen::Vector3f(3.0f + i, 1.0f, 0.0f), 0.0f, 0.0f, 0});
  for (LidarScan scan : {LidarScan{}, tiny, nan_scan}) {
    AfterGoodScans run;
    scan.timestamp = 0.5;
    const OdometryResult result = run.odometry.process(scan);
    EXPECT_EQ(result.status, OdometryStatus::kLost);
    EXPECT_TRUE(result.T_world_lidar.isApprox(run.predicted, 1e-9));
    // And it carries on afterwards.
    EXPECT_EQ(run.odometry.process(castScan(structuredRoom(), drivePose, 0.6, SyntheticSensor{})).status,
              OdometryStatus::kTracking);
  }
}

TEST(LidarOdometry, OnlyAFloorInViewIsDegenerateAndKeepsThePredictionWhereBlind) {
  AfterGoodScans run;
  SyntheticSensor short_range;  // all of the floor it sees is floor of the map
  short_range.max_range = 6.0;
  const OdometryResult result = run.odometry.process(castScan(testing::floorOnly(), drivePose, 0.5, short_range));
  EXPECT_EQ(result.status, OdometryStatus::kDegenerate);
  // A floor fixes height, roll and pitch only: x, y and yaw stay predicted.
  const Eigen::Isometry3d change = run.predicted.inverse() * result.T_world_lidar;
  EXPECT_LT(std::abs(change.translation().x()), 1e-3);
  EXPECT_LT(std::abs(change.translation().y()), 1e-3);
  EXPECT_LT(std::abs(logSE3(change)(5)), 1e-4);
}

TEST(LidarOdometry, TimeGoingBackIsRejectedAndAJumpDoesNotDiverge) {
  AfterGoodScans run;
  const OdometryResult back = run.odometry.process(castScan(structuredRoom(), drivePose, 0.3, SyntheticSensor{}));
  EXPECT_EQ(back.status, OdometryStatus::kRejected);
  // 0.4 s later (0.5 m further): the velocity is reset, the pose is still found.
  const OdometryResult jump = run.odometry.process(castScan(structuredRoom(), drivePose, 0.9, SyntheticSensor{}));
  EXPECT_EQ(jump.status, OdometryStatus::kTracking);
  const Eigen::Isometry3d error = (drivePose(0.0).inverse() * drivePose(0.9)).inverse() * jump.T_world_lidar;
  EXPECT_LT(error.translation().norm(), 0.05);
  // 2 s later, 2.4 m further: out of reach of a local registration. It must
  // not claim a wrong pose: lost, keeping the prediction of a robot standing
  // since the last scan (within the few centimetres of the last sweep's motion).
  const Eigen::Isometry3d before = jump.T_world_lidar;
  const OdometryResult far = run.odometry.process(castScan(structuredRoom(), drivePose, 2.9, SyntheticSensor{}));
  EXPECT_EQ(far.status, OdometryStatus::kLost);
  EXPECT_LT((before.inverse() * far.T_world_lidar).translation().norm(), 0.1);
}

// Kidnapped: the scans come from 2.4 m further on, out of reach of a local
// registration. Lost, lost, then the map restarts from the third at its
// predicted pose, and the scans after it are tracked again: relative motion
// right, even though the absolute pose kept the gap.
TEST(LidarOdometry, AMapTheScansNoLongerMatchRestartsAfterThreeLosses) {
  AfterGoodScans run;
  ASSERT_EQ(LidarOdometryConfig{}.registration.restart_after_lost, 3);
  std::vector<OdometryStatus> statuses;
  std::vector<Eigen::Isometry3d> poses;
  for (const double t : {2.9, 3.0, 3.1, 3.2, 3.3, 3.4}) {
    const OdometryResult r = run.odometry.process(castScan(structuredRoom(), drivePose, t, SyntheticSensor{}));
    statuses.push_back(r.status);
    poses.push_back(r.T_world_lidar);
  }
  EXPECT_EQ(statuses[0], OdometryStatus::kLost);
  EXPECT_EQ(statuses[1], OdometryStatus::kLost);
  EXPECT_EQ(statuses[2], OdometryStatus::kRestarted);
  EXPECT_EQ(statuses[3], OdometryStatus::kTracking);
  EXPECT_EQ(statuses[4], OdometryStatus::kTracking);
  EXPECT_EQ(statuses[5], OdometryStatus::kTracking);
  const Eigen::Isometry3d step = poses[3].inverse() * poses[5];
  const Eigen::Isometry3d true_step = drivePose(3.2).inverse() * drivePose(3.4);
  EXPECT_LT((true_step.inverse() * step).translation().norm(), 0.02);
  EXPECT_STREQ(statusName(OdometryStatus::kRestarted), "restarted");
}

}  // namespace
}  // namespace lvslam::lidar
