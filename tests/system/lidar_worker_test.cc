// The LiDAR worker poses camera frames as its header says, against a known
// constant-velocity motion: a frame gets the pose within its sweep once that
// sweep is registered, then the pose interpolated between that sweep and the
// next; frames no sweep covers are interpolated across the gap and marked
// unreliable; frames after the last sweep are extrapolated at finish().
#include "lvslam/system/lidar_worker.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <vector>

#include "lidar/synthetic_lidar.h"
#include "lvslam/core/se3.h"

namespace lvslam::system {
namespace {

// Pure translation at constant velocity: every pose the worker computes
// (constant-twist extrapolation, interpolation between sweeps) is then exact
// but for the registration's own error.
const Eigen::Isometry3d kStart = testing::drivePose(0.0);
const Eigen::Vector3d kVelocity(0.8, 0.3, 0.0);  // m/s, world frame

Eigen::Isometry3d truePose(double t) {
  Eigen::Isometry3d T = kStart;
  T.translation() += kVelocity * t;
  return T;
}

// T_odom_lidar: the odometry starts at the identity at the first scan (t = 0).
Eigen::Isometry3d trueOdomPose(double t) { return kStart.inverse() * truePose(t); }

struct Call {
  std::size_t index;
  LidarFrameRecord record;
  double registered;  // time stamp of the scan whose registration made the call
};

struct WorkerRun {
  std::vector<double> frame_times;
  std::vector<Call> calls;
  Trajectory scans;  // scanTrajectory() at the end
  Trajectory camera_poses;  // lidar_camera_poses of every answer, in order
};

SystemConfig lidarMode() {
  SystemConfig config;
  config.mode = RunMode::kLidar;
  config.loop.enabled = false;
  return config;
}

// Scans at 0.1 s steps except those in `missing`, two camera frames per
// sweep (3 and 7 hundredths in), then `extra_frames`, handed on in time
// order as the pipeline does: the end of the sweep before each scan, the
// scan, its frames.

WorkerRun runWorker(int sweeps, const std::vector<int>& missing, const std::vector<double>& extra_frames = {},
                    const SystemConfig& config = lidarMode(), const Calibration& calibration = {}) {
  LidarWorker worker(config, calibration);
  WorkerRun run;
  worker.onFramePosed([&](std::size_t index, const LidarFrameRecord& record) {
    run.calls.push_back({index, record, worker.scanTrajectory().back().t});
  });
  testing::SyntheticSensor sensor;
  sensor.columns = 360;
  const testing::SyntheticScene room = testing::structuredRoom();
  const auto addFrame = [&](double t) {
    run.frame_times.push_back(t);
    const FusionAnswer answer = worker.addFrame(t, {});
    run.camera_poses.insert(run.camera_poses.end(), answer.lidar_camera_poses.begin(), answer.lidar_camera_poses.end());
  };
  for (int k = 0; k < sweeps; ++k) {
    const double t0 = 0.1 * k;
    if (std::find(missing.begin(), missing.end(), k) == missing.end()) {
      worker.endSweep();
      worker.addScan(testing::castScan(room, truePose, t0, sensor));
    }
    addFrame(t0 + 0.03);
    addFrame(t0 + 0.07);
  }
  for (const double t : extra_frames) addFrame(t);
  worker.finish();
  run.scans = worker.scanTrajectory();
  return run;
}

std::vector<Call> callsFor(const WorkerRun& run, std::size_t index) {
  std::vector<Call> calls;
  for (const Call& c : run.calls)
    if (c.index == index) calls.push_back(c);
  return calls;
}

const StampedPose& scanAt(const WorkerRun& run, double t) {
  for (const StampedPose& p : run.scans)
    if (std::abs(p.t - t) < 1e-9) return p;
  ADD_FAILURE() << "no registered scan at " << t;
  return run.scans.front();
}

// How far a frame's pose is from the truth, seen from the scan whose
// registration made the call: the worker's part (which sweep, which time),
// without the odometry's own drift since the start (5 mm in 0.5 s here).
// Its registration error moves these by about 2 mm; a frame posed 10 ms
// off its time moves them by 8.5 mm.
constexpr double kTolerance = 0.005;
constexpr double kRotationTolerance = 0.1 * M_PI / 180.0;

Eigen::Isometry3d errorFromScan(const WorkerRun& run, const Call& call, double t) {
  const StampedPose& scan = scanAt(run, call.registered);
  const Eigen::Isometry3d truth = trueOdomPose(scan.t).inverse() * trueOdomPose(t);
  return truth.inverse() * (scan.T_world_frame.inverse() * *call.record.T_odom_lidar);
}

void expectPosedAt(const WorkerRun& run, const Call& call, double t) {
  ASSERT_TRUE(call.record.T_odom_lidar) << "frame at " << t;
  const Eigen::Isometry3d error = errorFromScan(run, call, t);
  EXPECT_LT(error.translation().norm(), kTolerance) << "frame at " << t << ", call at " << call.registered;
  EXPECT_LT(rotationAngle(error), kRotationTolerance) << "frame at " << t << ", call at " << call.registered;
}

TEST(LidarWorker, AFrameIsPosedInItsSweepThenInterpolatedBetweenThatSweepAndTheNext) {
  const WorkerRun run = runWorker(6, {});
  ASSERT_EQ(run.scans.size(), 6u);
  ASSERT_EQ(run.frame_times.size(), 12u);
  for (std::size_t i = 0; i < run.frame_times.size(); ++i) {
    const double t = run.frame_times[i];
    const int sweep = static_cast<int>(std::floor(t / 0.1));
    const std::vector<Call> calls = callsFor(run, i);
    // The last sweep has no next one: its frames keep their first pose.
    ASSERT_EQ(calls.size(), sweep == 5 ? 1u : 2u) << "frame at " << t;
    // First: when the sweep covering t is registered (the first sweep's
    // frames wait for the second: its length was unknown).
    EXPECT_NEAR(calls[0].registered, 0.1 * std::max(sweep, 1), 1e-9) << "frame at " << t;
    EXPECT_TRUE(calls[0].record.pose_reliable);
    expectPosedAt(run, calls[0], t);
    EXPECT_TRUE(calls[0].record.information.isApprox(calls[0].record.information.transpose(), 1e-9));
    EXPECT_GT(calls[0].record.information.trace(), 0.0);
    if (calls.size() < 2) continue;
    // Then: when the next sweep is registered, between the two registered
    // poses. The first sweep's frames are extrapolated back from the second
    // and third sweeps (what the code does), not interpolated between the
    // first two, although both are registered by then.
    const double next = 0.1 * (std::max(sweep, 1) + 1);
    EXPECT_NEAR(calls[1].registered, next, 1e-9);
    EXPECT_TRUE(calls[1].record.pose_reliable);
    const StampedPose &a = scanAt(run, next - 0.1), &b = scanAt(run, next);
    const Eigen::Isometry3d expected = interpolateAtTime(t, a.t, a.T_world_frame, b.t, b.T_world_frame);
    EXPECT_LT((calls[1].record.T_odom_lidar->matrix() - expected.matrix()).norm(), 1e-12) << "frame at " << t;
    expectPosedAt(run, calls[1], t);
  }
}

// A frame's first pose is its sweep's registered pose moved on by the
// sweep's motion, so it carries the velocity's error over the time moved
// besides the registration's: it states less information than that
// registration (the frames the same registration interpolates state all of
// it), and less the farther it lies from the registered middle of the sweep.
TEST(LidarWorker, APoseMovedOnFromItsSweepStatesTheVelocitysErrorToo) {
  const WorkerRun run = runWorker(6, {});
  std::vector<std::pair<double, Matrix6d>> registration_information;  // from the interpolated poses
  for (std::size_t i = 0; i < run.frame_times.size(); ++i) {
    const std::vector<Call> calls = callsFor(run, i);
    if (calls.size() == 2) registration_information.push_back({calls[1].registered, calls[1].record.information});
  }
  int compared = 0;
  for (std::size_t i = 0; i < run.frame_times.size(); ++i) {
    const Call first = callsFor(run, i).front();
    for (const auto& [registered, information] : registration_information) {
      if (std::abs(registered - first.registered) > 1e-9) continue;
      const Eigen::SelfAdjointEigenSolver<Matrix6d> less(information - first.record.information);
      EXPECT_GT(less.eigenvalues().minCoeff(), -1e-9 * information.trace()) << "frame at " << run.frame_times[i];
      EXPECT_LT(first.record.information.trace(), information.trace()) << "frame at " << run.frame_times[i];
      ++compared;
      break;
    }
  }
  EXPECT_GE(compared, 6);
  // The first sweep's frames (0.03 and 0.07 s) are moved back from the
  // second sweep's middle (about 0.15 s): the earlier one farther.
  const Matrix6d earlier = callsFor(run, 0).front().record.information;
  const Matrix6d later = callsFor(run, 1).front().record.information;
  EXPECT_LT(earlier.trace(), later.trace());
}

TEST(LidarWorker, FramesNoSweepCoversAreInterpolatedAcrossTheGapAndMarkedUnreliable) {
  // Scans 4 and 5 are missing: frames between 0.4 and 0.6 s have no sweep;
  // then two more past the last sweep's end (1.0 s), extrapolated at the end.
  const WorkerRun run = runWorker(10, {4, 5}, {1.02, 1.05});
  ASSERT_EQ(run.scans.size(), 8u);
  for (std::size_t i = 0; i < run.frame_times.size(); ++i) {
    const double t = run.frame_times[i];
    const std::vector<Call> calls = callsFor(run, i);
    ASSERT_FALSE(calls.empty()) << "frame at " << t;
    const Call& last = calls.back();
    for (const Call& call : calls) expectPosedAt(run, call, t);
    if (t > 0.4 && t < 0.6) {
      ASSERT_EQ(calls.size(), 1u) << "frame at " << t;
      EXPECT_NEAR(last.registered, 0.6, 1e-9);
      EXPECT_FALSE(last.record.pose_reliable) << "frame at " << t;
      const StampedPose &a = scanAt(run, 0.3), &b = scanAt(run, 0.6);
      const Eigen::Isometry3d expected = interpolateAtTime(t, a.t, a.T_world_frame, b.t, b.T_world_frame);
      EXPECT_LT((last.record.T_odom_lidar->matrix() - expected.matrix()).norm(), 1e-12) << "frame at " << t;
    } else if (t > 1.0) {
      ASSERT_EQ(calls.size(), 1u) << "frame at " << t;
      EXPECT_FALSE(last.record.pose_reliable) << "frame at " << t;
    } else {
      EXPECT_TRUE(last.record.pose_reliable) << "frame at " << t;
    }
  }
  // Sweep 3's frames: first in their sweep, then between 0.3 and 0.6 s.
  const std::vector<Call> sweep3 = callsFor(run, 6);
  ASSERT_EQ(sweep3.size(), 2u);
  EXPECT_NEAR(sweep3[0].registered, 0.3, 1e-9);
  EXPECT_NEAR(sweep3[1].registered, 0.6, 1e-9);
}

TEST(LidarWorker, FusedModeHandsTheInterpolatedPosesOfReliableFramesToTheVisualSideInTheCameraFrame) {
  SystemConfig config;  // fused, LiDAR pose priors on
  config.loop.enabled = false;
  ASSERT_TRUE(config.visual.modules.use_lidar_pose_priors);
  Calibration calibration;
  calibration.camera = PinholeCamera(640, 480, 450.0, 450.0, 320.0, 240.0);
  Eigen::Matrix3d R_camera_lidar;
  R_camera_lidar << 0, -1, 0, 0, 0, -1, 1, 0, 0;  // camera z along the LiDAR's x
  calibration.T_camera_lidar = makePose(R_camera_lidar, Eigen::Vector3d(0.05, -0.1, 0.02));
  // Scan 4 is missing: frames between 0.4 and 0.5 s are unreliable and not handed on.
  const WorkerRun run = runWorker(8, {4}, {}, config, calibration);
  std::vector<Call> interpolated;  // second calls, the reliable ones, in the order made
  std::vector<std::size_t> seen(run.frame_times.size(), 0);
  for (const Call& c : run.calls)
    if (++seen[c.index] == 2 && c.record.pose_reliable) interpolated.push_back(c);
  // Each goes with the answer to the next frame; the two made at finish()
  // (sweep 6's frames, when the last sweep is registered) have none.
  ASSERT_GE(interpolated.size(), 6u);
  ASSERT_EQ(run.camera_poses.size(), interpolated.size() - 2);
  for (std::size_t j = 0; j < run.camera_poses.size(); ++j) {
    const Call& c = interpolated[j];
    const double t = run.frame_times[c.index];
    EXPECT_DOUBLE_EQ(run.camera_poses[j].t, t);
    EXPECT_FALSE(t > 0.4 && t < 0.5) << "frame at " << t;
    const Eigen::Isometry3d expected = *c.record.T_odom_lidar * calibration.T_camera_lidar.inverse();
    EXPECT_LT((run.camera_poses[j].T_world_frame.matrix() - expected.matrix()).norm(), 1e-12) << "frame at " << t;
  }
}

}  // namespace
}  // namespace lvslam::system
