// The fused online estimator on synthetic subsystem estimates with known
// covariances: the closed-form weighting, the chi-square gate on a jump in
// either subsystem, and a degenerate LiDAR direction taken from vision.
#include "lvslam/system/online/fused_estimator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>

#include "lvslam/core/error.h"
#include "lvslam/core/se3.h"

namespace lvslam::system {
namespace {

constexpr double kDt = 1.0 / 15.0;  // a camera at 15 Hz

Eigen::Isometry3d at(double x, double y = 0.0, double z = 0.0) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

Matrix6d isotropic(double sigma_m, double sigma_rad) {
  Vector6d d;
  d << Eigen::Vector3d::Constant(1.0 / (sigma_m * sigma_m)), Eigen::Vector3d::Constant(1.0 / (sigma_rad * sigma_rad));
  return d.asDiagonal();
}

FusedEstimatorConfig exactConfig() {
  FusedEstimatorConfig c;
  c.lidar_drift_m = c.lidar_drift_deg = 0.0;  // only the stated covariances
  c.visual_drift_m = c.visual_drift_deg = 0.0;
  c.visual_pixel_sigma = 1.0;
  c.huber_delta = 1e6;
  c.max_iterations = 50;
  return c;
}

LidarFrameInput lidarAt(const Eigen::Isometry3d& T, const Matrix6d& information) { return {T, information}; }

// A pose of map 0, which stands at the world's origin.
VisualFrameInput visualAt(const Eigen::Isometry3d& T_map_camera, const Matrix6d& information) {
  VisualFrameInput v;
  v.T_map_camera = T_map_camera;
  v.information = information;
  return v;
}

TEST(FusedEstimator, TwoSubsystemsGiveTheClosedFormWeightedMean) {
  FusedEstimator estimator(exactConfig());
  const Matrix6d H_lidar = isotropic(0.01, 0.001), H_visual = isotropic(0.005, 0.001);
  ASSERT_TRUE(estimator.add(0.0, lidarAt(at(0), H_lidar), visualAt(at(0), H_visual)).T_world_camera);
  // The LiDAR says 10 cm, vision 11 cm along x; the motion model (no
  // velocity yet) says 0 with sigma 2 m/s x dt.
  const FusedFrameOutput out = estimator.add(kDt, lidarAt(at(0.10), H_lidar), visualAt(at(0.11), H_visual));
  ASSERT_TRUE(out.T_world_camera && out.lidar_used && out.visual_used);
  EXPECT_TRUE(out.gated.empty());
  // Without drift the odometry frame stays where the first pose put it: the
  // LiDAR pose enters with its own covariance. The visual map's place in the
  // world is known only through its poses: without drift vision measures the
  // step from frame 0, with both poses' covariances.
  const double w_lidar = 1.0 / (0.01 * 0.01), w_visual = 1.0 / (2.0 * 0.005 * 0.005);
  const double w_motion = 1.0 / ((2.0 * kDt) * (2.0 * kDt));
  const double expected = (w_lidar * 0.10 + w_visual * 0.11) / (w_lidar + w_visual + w_motion);
  EXPECT_NEAR(out.T_world_camera->translation().x(), expected, 1e-7);
  EXPECT_NEAR(out.T_world_camera->translation().y(), 0.0, 1e-9);
  // Its variance is the inverse of the summed information (within 0.2 %:
  // the map's rotation, known to 1 mrad, moves a pose 0.11 m from its origin).
  ASSERT_TRUE(out.covariance);
  const double variance = 1.0 / (w_lidar + w_visual + w_motion);
  EXPECT_NEAR((*out.covariance)(0, 0), variance, 2e-3 * variance);
}

struct StraightRun {
  std::vector<FusedFrameOutput> outputs;
};

// 30 frames at 0.75 m/s along x; `lidar_offset` / `visual_offset` shift one
// subsystem's pose at frame `glitch`.
StraightRun straightRun(const Eigen::Vector3d& lidar_offset, const Eigen::Vector3d& visual_offset, int glitch) {
  FusedEstimatorConfig config;
  config.visual_pixel_sigma = 1.0;  // H_visual below is the visual pose's whole information
  FusedEstimator estimator(config);
  const Matrix6d H_lidar = isotropic(0.002, 0.0005), H_visual = isotropic(0.004, 0.001);
  StraightRun run;
  for (int j = 0; j < 30; ++j) {
    const double x = 0.05 * j;
    Eigen::Isometry3d T_lidar = at(x), T_visual = at(x);
    if (j == glitch) {
      T_lidar.translation() += lidar_offset;
      T_visual.translation() += visual_offset;
    }
    run.outputs.push_back(estimator.add(kDt * j, lidarAt(T_lidar, H_lidar), visualAt(T_visual, H_visual)));
  }
  return run;
}

TEST(FusedEstimator, AJumpInTheLidarIsGatedAndLogged) {
  const StraightRun run = straightRun(Eigen::Vector3d(0.0, 0.10, 0.0), Eigen::Vector3d::Zero(), 20);
  const FusedFrameOutput& glitch = run.outputs[20];
  ASSERT_EQ(glitch.gated.size(), 1u);
  EXPECT_EQ(glitch.gated[0].source, FactorSource::kLidar);
  EXPECT_GT(glitch.gated[0].chi_square, glitch.gated[0].threshold);
  EXPECT_FALSE(glitch.lidar_used);
  EXPECT_TRUE(glitch.visual_used);
  EXPECT_LT((glitch.T_world_camera->translation() - Eigen::Vector3d(1.0, 0, 0)).norm(), 0.005);
  // Only the jump: the steps before it and the return after it pass.
  for (int j = 0; j < 30; ++j) {
    if (j == 20) continue;
    EXPECT_TRUE(run.outputs[static_cast<std::size_t>(j)].gated.empty()) << j;
  }
}

TEST(FusedEstimator, AJumpInVisionIsGatedAndLogged) {
  const StraightRun run = straightRun(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, 0.1), 20);
  const FusedFrameOutput& glitch = run.outputs[20];
  ASSERT_EQ(glitch.gated.size(), 1u);
  EXPECT_EQ(glitch.gated[0].source, FactorSource::kVisual);
  EXPECT_FALSE(glitch.gated[0].reason.empty());
  EXPECT_TRUE(glitch.lidar_used);
  EXPECT_LT((glitch.T_world_camera->translation() - Eigen::Vector3d(1.0, 0, 0)).norm(), 0.003);
}

// A LiDAR degenerate along x (a corridor): its odometry stood still along x
// while the robot moved; vision saw the motion. The output follows vision
// along x and agrees with both across it.
TEST(FusedEstimator, ADegenerateLidarDirectionTakesTheVisualEstimate) {
  FusedEstimator estimator(FusedEstimatorConfig{});
  Matrix6d H_lidar = isotropic(0.002, 0.0005);
  H_lidar(0, 0) = 0.0;  // nothing along x
  const Matrix6d H_visual = isotropic(0.004, 0.001);
  FusedFrameOutput last;
  for (int j = 0; j < 40; ++j) {
    const double x = 0.05 * j;
    last = estimator.add(kDt * j, lidarAt(at(0.0, 0.0, 0.0), H_lidar), visualAt(at(x), H_visual));
    EXPECT_TRUE(last.gated.empty()) << j;
  }
  ASSERT_TRUE(last.T_world_camera);
  EXPECT_NEAR(last.T_world_camera->translation().x(), 0.05 * 39, 0.005);  // the LiDAR says 0
  EXPECT_NEAR(last.T_world_camera->translation().y(), 0.0, 0.002);
}

// The LiDAR walks sideways, 1 mm a frame (4 s, 6 cm at the end), each
// step well within its stated 1 cm; vision, also stated at 1 cm, stays on
// the truth (y = 0). A registration that holds the odometry to its map
// drifts by the odometry's small rate (5 mm per sqrt(m), vision's map
// 20 mm), so the output follows the LiDAR's walk. A degenerate one does not
// hold it: each new one walks the odometry's frame by its own covariance,
// and vision's map, now the steadier frame, keeps the output.
double lateralOffsetAfterLidarWalk(bool degenerate) {
  FusedEstimatorConfig config;
  config.visual_pixel_sigma = 1.0;
  FusedEstimator estimator(config);
  const Matrix6d H_lidar = isotropic(0.01, 0.002), H_visual = isotropic(0.01, 0.002);
  FusedFrameOutput out;
  for (int j = 0; j < 60; ++j) {
    LidarFrameInput lidar = lidarAt(at(0.05 * j, 0.001 * j), H_lidar);
    lidar.degenerate = degenerate;
    lidar.registration = static_cast<std::size_t>(j + 1);
    out = estimator.add(kDt * j, lidar, visualAt(at(0.05 * j), H_visual));
    EXPECT_TRUE(out.gated.empty()) << j;
  }
  EXPECT_TRUE(out.T_world_camera);
  return out.T_world_camera ? out.T_world_camera->translation().y() : 1.0;
}

// Per frame (5 cm of path) the held odometry's frame may move 1.1 mm and
// vision's map 4.5 mm: the low frequency goes 16:1 to the LiDAR. A
// degenerate registration adds its own 1 cm: 5:1 to vision.
TEST(FusedEstimator, ADegenerateRegistrationLetsTheOdometryFrameWalkByItsOwnCovariance) {
  const double lidar_offset = 0.001 * 59;
  EXPECT_GT(lateralOffsetAfterLidarWalk(false), 2.0 / 3.0 * lidar_offset);
  EXPECT_LT(std::abs(lateralOffsetAfterLidarWalk(true)), 1.0 / 3.0 * lidar_offset);
}

// The LiDAR lost x for frames 10..29 (its odometry dead-reckoned 20 % slow:
// 20 cm short by frame 29), then sees x again from frame 30 on, with the
// right motion but from the dead-reckoned position. Its odometry frame
// slipped along x while it was blind, so only its motion from frame 30 on
// enters: the output stays on vision's (true) position instead of being
// pulled back toward the LiDAR's.
TEST(FusedEstimator, ADirectionTheLidarSeesAgainBringsItsMotionNotItsDeadReckonedPosition) {
  FusedEstimator estimator(FusedEstimatorConfig{});
  const Matrix6d H_full = isotropic(0.002, 0.0005), H_visual = isotropic(0.004, 0.001);
  Matrix6d H_blind_x = H_full;
  H_blind_x(0, 0) = 0.0;
  double lidar_x = 0.0;
  for (int j = 0; j < 40; ++j) {
    const double x = 0.05 * j;
    if (j > 0) lidar_x += (j >= 10 && j < 30) ? 0.04 : 0.05;
    const bool blind = j >= 10 && j < 30;
    const FusedFrameOutput out =
        estimator.add(kDt * j, lidarAt(at(lidar_x), blind ? H_blind_x : H_full), visualAt(at(x), H_visual));
    ASSERT_TRUE(out.T_world_camera);
    EXPECT_TRUE(out.gated.empty()) << j;
    EXPECT_TRUE(out.lidar_used) << j;
    EXPECT_NEAR(out.T_world_camera->translation().x(), x, 0.01) << j;
  }
}

// Vision alone (no LiDAR pose for a while: a drop-out) carries the output.
TEST(FusedEstimator, ALidarDropOutIsBridgedByVision) {
  FusedEstimator estimator(FusedEstimatorConfig{});
  const Matrix6d H_lidar = isotropic(0.002, 0.0005), H_visual = isotropic(0.004, 0.001);
  FusedFrameOutput out;
  for (int j = 0; j < 40; ++j) {
    const double x = 0.05 * j;
    std::optional<LidarFrameInput> lidar;
    if (j < 10 || j >= 30) lidar = lidarAt(at(x), H_lidar);
    out = estimator.add(kDt * j, lidar, visualAt(at(x), H_visual));
    ASSERT_TRUE(out.T_world_camera);
    EXPECT_NEAR(out.T_world_camera->translation().x(), x, 0.003) << j;
    EXPECT_EQ(out.lidar_used, j < 10 || j >= 30) << j;  // the gap's step: from the last LiDAR pose
  }
}

// The visual map is corrected at frame 20 (everything in it moves 5 cm
// along y): from then on vision's poses are in the moved map. Its node
// carries the correction, so the output does not follow the move.
TEST(FusedEstimator, AMapCorrectionMovesTheMapNotTheOutput) {
  FusedEstimator estimator(FusedEstimatorConfig{});
  const Matrix6d H_lidar = isotropic(0.01, 0.002), H_visual = isotropic(0.002, 0.0005);
  const Eigen::Isometry3d T_new_old = at(0.0, 0.05);
  for (int j = 0; j < 40; ++j) {
    const double x = 0.05 * j;
    VisualFrameInput v = visualAt(j < 20 ? at(x) : T_new_old * at(x), H_visual);
    if (j == 20) v.T_new_old = T_new_old;
    const FusedFrameOutput out = estimator.add(kDt * j, lidarAt(at(x), H_lidar), v);
    ASSERT_TRUE(out.T_world_camera);
    EXPECT_TRUE(out.gated.empty()) << j;
    EXPECT_TRUE(out.visual_used) << j;
    EXPECT_NEAR(out.T_world_camera->translation().y(), 0.0, 0.002) << j;
    EXPECT_NEAR(out.T_world_camera->translation().x(), x, 0.002) << j;
  }
}

// Vision is lost after frame 8 and the robot stops at frame 9 (x = 0.09);
// a second map starts at frame 21 with frame 8 as its first view, at its
// origin. The LiDAR sees nothing along x, and the motion model carries the
// robot on through the gap: the first view places the new map, so the
// output comes back to where the robot stands.
TEST(FusedEstimator, ANewMapIsPlacedByItsFirstView) {
  FusedEstimator estimator(FusedEstimatorConfig{});
  Matrix6d H_lidar = isotropic(0.002, 0.0005);
  H_lidar(0, 0) = 0.0;
  const Matrix6d H_visual = isotropic(0.004, 0.001);
  for (int j = 0; j < 40; ++j) {
    const double x = 0.01 * std::min(j, 9);
    std::optional<VisualFrameInput> v;
    if (j <= 8) v = visualAt(at(x), H_visual);
    if (j >= 21) {
      v = visualAt(at(x - 0.08), H_visual);
      v->map_id = 1;
    }
    if (j == 21) v->initial_view = StampedPose{kDt * 8, at(0.0)};
    const FusedFrameOutput out = estimator.add(kDt * j, lidarAt(at(0.0), H_lidar), v);
    ASSERT_TRUE(out.T_world_camera);
    if (j <= 8) {
      EXPECT_NEAR(out.T_world_camera->translation().x(), x, 0.002) << j;
    } else if (j >= 21) {
      // Within the stop's share the motion model keeps (without the first
      // view the output stays where the motion model took it, 12 cm on).
      EXPECT_NEAR(out.T_world_camera->translation().x(), x, 0.03) << j;
    }
  }
}

TEST(FusedEstimator, NothingBeforeTheFirstLidarPose) {
  FusedEstimator estimator(FusedEstimatorConfig{});
  EXPECT_FALSE(estimator.add(0.0, std::nullopt, visualAt(at(0), isotropic(0.01, 0.01))).T_world_camera);
  EXPECT_TRUE(estimator.takeGraph().nodes.empty());
}

// Online the estimator keeps history_s of its graph in memory, so its
// memory does not grow with the run; the window never reads beyond that, so
// every output is the one an estimator keeping the whole run gives, and the
// graph it let go (on disk) with the part it holds is that estimator's
// graph. 67 s at 15 Hz, both subsystems noisy about a curved path, vision
// lost for 3 s at 40 s.
TEST(FusedEstimator, ALongRunKeepsItsRecentHistoryOnlyAndOutputsTheSame) {
  FusedEstimatorConfig recent = FusedEstimatorConfig{}, whole = FusedEstimatorConfig{};
  recent.history_s = 5.0;
  whole.history_s = -1.0;
  FusedEstimator kept_recent(recent), kept_whole(whole);
  const Matrix6d H_lidar = isotropic(0.01, 0.002), H_visual = isotropic(0.005, 0.001);
  const int frames = 1000;
  for (int i = 0; i < frames; ++i) {
    const double t = i * kDt;
    Eigen::Isometry3d T = at(std::sin(0.1 * t), 0.5 * t, 0.0);
    T.linear() = expSO3(Eigen::Vector3d(0.0, 0.0, 0.05 * t));
    const Eigen::Isometry3d T_lidar = T * at(0.003 * std::sin(7.0 * i), 0.0, 0.002 * std::cos(5.0 * i));
    const Eigen::Isometry3d T_visual = T * at(0.0, 0.002 * std::sin(3.0 * i), 0.0);
    const bool seen = t < 40.0 || t > 43.0;
    const std::optional<VisualFrameInput> visual = seen ? std::optional(visualAt(T_visual, H_visual)) : std::nullopt;
    const FusedFrameOutput a = kept_recent.add(t, lidarAt(T_lidar, H_lidar), visual);
    const FusedFrameOutput b = kept_whole.add(t, lidarAt(T_lidar, H_lidar), visual);
    ASSERT_TRUE(a.T_world_camera && b.T_world_camera);
    ASSERT_TRUE(a.T_world_camera->matrix() == b.T_world_camera->matrix()) << "frame " << i;
    ASSERT_EQ(a.camera_node, b.camera_node);
  }
  EXPECT_LT(kept_recent.nodesHeld(), kept_whole.nodesHeld() / 2);
  const EstimatorGraph a = kept_recent.takeGraph(), b = kept_whole.takeGraph();
  EXPECT_EQ(b.camera_nodes.size(), static_cast<std::size_t>(frames));
  EXPECT_EQ(a.camera_nodes, b.camera_nodes);
  EXPECT_EQ(a.times, b.times);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    ASSERT_TRUE(a.nodes[i].T_world_camera.matrix() == b.nodes[i].T_world_camera.matrix()) << "node " << i;
    ASSERT_EQ(a.nodes[i].fixed, b.nodes[i].fixed) << "node " << i;
  }
  ASSERT_EQ(a.factors.size(), b.factors.size());
  auto fb = b.factors.begin();
  for (const PoseFactor& fa : a.factors) {
    ASSERT_EQ(fa.from, fb->from);
    ASSERT_EQ(fa.to, fb->to);
    ASSERT_EQ(fa.source, fb->source);
    ASSERT_TRUE(fa.T_from_to.matrix() == fb->T_from_to.matrix()) << fa.from << " -> " << fa.to;
    ASSERT_TRUE(fa.information == fb->information) << fa.from << " -> " << fa.to;
    ++fb;
  }
}

// The RMS distance of errors from their mean.
double spread(const std::vector<Eigen::Vector3d>& errors) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& e : errors) mean += e / static_cast<double>(errors.size());
  double squared = 0.0;
  for (const Eigen::Vector3d& e : errors) squared += (e - mean).squaredNorm();
  return std::sqrt(squared / static_cast<double>(errors.size()));
}

// A LiDAR ten times noisier than it states (in sigma, translation and
// rotation alike; its pose held over a sweep, 10 Hz against the camera's
// 15 Hz) beside a vision that states its noise right, neither drifting: the
// step gate weighs the LiDAR down by what its steps show (frames that share
// a sweep step less than their noise, so that reads a third or so of the
// hundred its variance is understated by, far above 1), keeps vision as
// stated, and the output is better than the LiDAR's by half.
TEST(FusedEstimator, ALidarNoisierThanItStatesIsWeighedDown) {
  FusedEstimatorConfig config = exactConfig();
  config.huber_delta = FusedEstimatorConfig{}.huber_delta;
  FusedEstimator estimator(config);
  const double lidar_m = 0.001, lidar_rad = 0.0005, understated = 10.0, visual_m = 0.004, visual_rad = 0.001;
  const Matrix6d H_lidar = isotropic(lidar_m, lidar_rad), H_visual = isotropic(visual_m, visual_rad);
  std::mt19937 rng(7);
  std::normal_distribution<double> unit(0.0, 1.0);
  const auto noise = [&](double sigma_m, double sigma_rad) -> Eigen::Isometry3d {
    Vector6d xi;
    xi << sigma_m * unit(rng), sigma_m * unit(rng), sigma_m * unit(rng), sigma_rad * unit(rng),
        sigma_rad * unit(rng), sigma_rad * unit(rng);
    return expSE3(xi);
  };
  Eigen::Isometry3d lidar_error = Eigen::Isometry3d::Identity();
  std::vector<Eigen::Vector3d> output_errors, lidar_errors;
  FusedFrameOutput out;
  for (int j = 0; j < 300; ++j) {
    if (j % 3 != 1) lidar_error = noise(understated * lidar_m, understated * lidar_rad);  // two sweeps in three frames
    const Eigen::Isometry3d truth = at(0.05 * j);
    out = estimator.add(kDt * j, lidarAt(truth * lidar_error, H_lidar),
                        visualAt(truth * noise(visual_m, visual_rad), H_visual));
    ASSERT_TRUE(out.T_world_camera);
    if (j < 100) continue;
    output_errors.push_back(out.T_world_camera->translation() - truth.translation());
    lidar_errors.push_back(lidar_error.translation());
  }
  const double variance_ratio = understated * understated;
  EXPECT_GT(out.lidar_noise_scale, 0.1 * variance_ratio);
  EXPECT_LT(out.lidar_noise_scale, 2.0 * variance_ratio);
  EXPECT_LT(out.visual_noise_scale, 1.5);
  // The world is the first LiDAR pose, itself off by the LiDAR's noise: the
  // output's error about its mean, as an ATE's alignment would take it.
  EXPECT_LT(spread(output_errors), 0.5 * spread(lidar_errors));
}

TEST(FusedEstimator, TheHistoryMustOutlastTheWindow) {
  FusedEstimatorConfig config;
  config.history_s = config.window_s;
  EXPECT_THROW(FusedEstimator{config}, Error);
}

}  // namespace
}  // namespace lvslam::system
