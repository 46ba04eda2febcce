// The whole system on short simulated room sequences (config/sim.yaml), as
// `lvslam run` does it: accuracy per mode against the exact ground truth,
// the detection module across a camera blackout, and determinism.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "lvslam/core/se3.h"
#include "lvslam/system/run_recording.h"
#include "support/record_files.h"
#include "support/temp_dir.h"
#include "support/trajectory_at.h"
#include "system/sim_cache.h"

namespace lvslam::system {
namespace {

// 8 s: the robot starts from rest and makes about a third of its loop.
sim::SimOptions roomOptions() { return lvslam::testing::roomSimulation(8.0, 1); }
const char* const kRoomName = "room-8s-seed1";

// In its first seconds the young visual map disagrees with the LiDAR now and
// then (2-3 cm in a frame) and the output goes back to the LiDAR for at least
// 10 frames each time; from about 5 s on vision is in use. The blackout starts
// at 6 s (at 5 s whether vision was back in time was a matter of a few frames)
// and leaves 3.5 s to re-initialise and prove itself again.
constexpr double kBlackoutBegin = 6.0, kBlackoutEnd = 7.5;
sim::SimOptions blackoutOptions() {
  sim::SimOptions o = roomOptions();
  o.duration = 11.0;
  o.camera_blackout = sim::TimeInterval{kBlackoutBegin, kBlackoutEnd};
  return o;
}
const char* const kBlackoutName = "room-11s-seed1-blackout-6-7.5";

struct SimRun {
  RunResult result;
  Trajectory ground_truth;
};

SimRun runOn(const std::string& name, const sim::SimOptions& options, RunMode mode, bool deterministic) {
  const std::string dir = lvslam::testing::cachedSimulation(name, options);
  SystemConfig config = loadSystemConfig(YamlConfig::loadFile(std::string(LVSLAM_SOURCE_DIR) + "/config/sim.yaml"));
  config.mode = mode;
  config.deterministic = deterministic;
  RecordingRequest request;
  request.sequence_dir = dir;
  Recording recording = openRecording(request);
  SimRun run{runRecording(recording, config), *recording.ground_truth};
  return run;
}

void printFigures(const char* what, const RunResult& r) {
  const auto& ate = r.accuracy->ate.stats;
  std::printf("[ figures  ] %s: ATE rmse %.4f mean %.4f max %.4f m over %zu poses of %zu images, "
              "%zu from vision, %zu switches, %.2f fusion lines per frame\n",
              what, ate.rmse, ate.mean, ate.max, r.output.trajectory.size(), r.summary.images,
              r.summary.visual_output, r.summary.switches, r.summary.fusion_lines_per_frame);
}

// How far each output step (consecutive poses) is from the true step, in m.
std::vector<double> stepErrors(const Trajectory& est, const Trajectory& gt) {
  std::vector<double> errors;
  for (std::size_t k = 1; k < est.size(); ++k) {
    const Eigen::Isometry3d step = est[k - 1].T_world_frame.inverse() * est[k].T_world_frame;
    const Eigen::Isometry3d true_step =
        lvslam::testing::poseAt(gt, est[k - 1].t).inverse() * lvslam::testing::poseAt(gt, est[k].t);
    errors.push_back((true_step.inverse() * step).translation().norm());
  }
  return errors;
}

std::string fileText(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

// ---- accuracy per mode ----

TEST(SystemEndToEnd, LidarModeMeetsTheLidarTarget) {
  const SimRun run = runOn(kRoomName, roomOptions(), RunMode::kLidar, false);
  const RunResult& r = run.result;
  ASSERT_TRUE(r.accuracy);
  printFigures("lidar", r);
  EXPECT_EQ(r.accuracy->alignment, eval::Alignment::kSE3);
  EXPECT_EQ(r.output.trajectory.size(), r.summary.images);  // a pose at every camera frame
  EXPECT_EQ(r.summary.images, 120u);
  // The LiDAR odometry's registered sweeps, each frame interpolated between
  // the two around it (the refinement): about 1 cm on 60 s. Online a frame
  // has only the sweep covering it, extrapolated within it: a little worse.
  ASSERT_TRUE(r.accuracy_refined);
  EXPECT_LT(r.accuracy_refined->ate.stats.rmse, 0.010);
  EXPECT_LT(r.accuracy->ate.stats.rmse, 0.015);
  EXPECT_LE(r.accuracy_refined->ate.stats.rmse, r.accuracy->ate.stats.rmse);
}

// Seed 2 of the gate: at its third scan the two-scan map matches 0.49 of a
// rightly registered scan (the second matched 0.73). Judged against an
// absolute 0.5, that scan was lost and the odometry never recovered (ATE
// 0.48 m over these 3 s, 10 m over 60 s).
TEST(SystemEndToEnd, LidarModeKeepsTrackOfAYoungOutdoorMap) {
  sim::SimOptions options;
  options.scenario = "gate";
  options.duration = 3.0;
  options.seed = 2;
  const SimRun run = runOn("gate-3s-seed2", options, RunMode::kLidar, false);
  const RunResult& r = run.result;
  ASSERT_TRUE(r.accuracy);
  printFigures("lidar, gate seed 2", r);
  for (const ScanRecord& scan : r.records.scans)
    EXPECT_TRUE(scan.status == "initialized" || scan.status == "tracking") << scan.status << " at t=" << scan.t;
  EXPECT_LT(r.accuracy->ate.stats.rmse, 0.02);
}

TEST(SystemEndToEnd, VisualModeMeetsTheVisualTargetOnAShortRun) {
  const SimRun run = runOn(kRoomName, roomOptions(), RunMode::kVisual, false);
  const RunResult& r = run.result;
  ASSERT_TRUE(r.accuracy);
  printFigures("visual", r);
  EXPECT_TRUE(r.output.metric);  // started on LiDAR depth hints
  EXPECT_EQ(r.accuracy->alignment, eval::Alignment::kSE3);
  EXPECT_EQ(r.summary.visual_maps, 1u);  // never lost in the room
  EXPECT_GE(r.output.trajectory.size(), r.summary.images * 8 / 10);  // initialised within the first 20 %
  // The visual target is 5 cm on 60 s; on these 8 s keyframe depths from the
  // deskewed raw LiDAR points keep vision well inside 3 cm, which the metric
  // start alone does not reliably do (docs/history/2026-11-fusion-sessions.md,
  // "Visual mode: keyframe depths from raw LiDAR points").
  EXPECT_LT(r.accuracy->ate.stats.rmse, 0.03);
}

TEST(SystemEndToEnd, FusedModeUsesVisionAndStaysAccurate) {
  const SimRun run = runOn(kRoomName, roomOptions(), RunMode::kFused, false);
  const RunResult& r = run.result;
  ASSERT_TRUE(r.accuracy);
  printFigures("fused", r);
  EXPECT_EQ(r.output.trajectory.size(), r.summary.images);  // the LiDAR bridges every frame vision lacks
  EXPECT_GT(r.summary.visual_output, r.summary.images / 4);  // vision is in use for a good part
  EXPECT_GT(r.summary.fusion_lines_per_frame, 1.0);
  // Keyframe keypoints take their depth from the raw scans (the default),
  // and the records say how many did.
  std::size_t keyframes = 0, keyframes_with_depths = 0;
  for (const VisualFrameRecord& v : r.records.visual) {
    if (!v.result.keyframe) continue;
    ++keyframes;
    keyframes_with_depths += v.keypoint_depths > 0 ? 1 : 0;
    EXPECT_LE(v.keypoint_depths, static_cast<std::size_t>(v.result.health.keypoints));
  }
  EXPECT_GT(keyframes_with_depths, keyframes * 8 / 10);
  // The estimator: where vision is admitted, the LiDAR's factor is there too.
  EXPECT_GT(r.summary.fused_output, r.summary.visual_output * 9 / 10);
  EXPECT_LE(r.summary.fused_output, r.summary.visual_output);
  // Online, fused is below the LiDAR alone on the same frames, and the
  // offline refinement is no worse than the online output.
  const SimRun lidar = runOn(kRoomName, roomOptions(), RunMode::kLidar, false);
  ASSERT_TRUE(lidar.result.accuracy && r.accuracy_refined);
  std::printf("[ figures  ] online ATE rmse fused %.4f, lidar %.4f; refined fused %.4f\n", r.accuracy->ate.stats.rmse,
              lidar.result.accuracy->ate.stats.rmse, r.accuracy_refined->ate.stats.rmse);
  EXPECT_LT(r.accuracy->ate.stats.rmse, lidar.result.accuracy->ate.stats.rmse);
  EXPECT_LE(r.accuracy_refined->ate.stats.rmse, r.accuracy->ate.stats.rmse);
}

// ---- LiDAR drop-out ----

// No sweep from 6 to 8 s. Frames in the gap have no LiDAR measurement (the
// LiDAR's own output bridges them by interpolation), so the fused output is
// vision's there and takes the LiDAR back without a jump. Guards against
// entering the gap's frames as measurements extrapolated backwards from the
// next sweep, which put fused far behind vision here
// (docs/history/2026-11-27-online-estimator.md, "LiDAR drop-out").
TEST(SystemEndToEnd, ALidarDropOutIsBridgedByVision) {
  sim::SimOptions options = roomOptions();
  options.duration = 11.0;
  options.lidar_dropout = sim::TimeInterval{6.0, 8.0};
  const char* const name = "room-11s-seed1-lidar-dropout-6-8";
  const SimRun fused = runOn(name, options, RunMode::kFused, false);
  const SimRun visual = runOn(name, options, RunMode::kVisual, false);
  ASSERT_TRUE(fused.result.accuracy && visual.result.accuracy);
  printFigures("fused, LiDAR drop-out", fused.result);
  printFigures("visual, LiDAR drop-out", visual.result);
  EXPECT_EQ(fused.result.output.trajectory.size(), fused.result.summary.images);
  // The bound: across a drop-out fused stays within 10 % of vision alone.
  EXPECT_LT(fused.result.accuracy->ate.stats.rmse, 1.1 * visual.result.accuracy->ate.stats.rmse);
  const std::vector<double> errors = stepErrors(fused.result.output.trajectory, fused.ground_truth);
  EXPECT_LT(*std::max_element(errors.begin(), errors.end()), 0.02);
}

// ---- blackout, continuity, determinism ----

TEST(SystemEndToEnd, BlackoutSwitchesToLidarAndBackDeterministically) {
  const sim::SimOptions options = blackoutOptions();
  const SimRun det1 = runOn(kBlackoutName, options, RunMode::kFused, true);
  const SimRun det2 = runOn(kBlackoutName, options, RunMode::kFused, true);
  const SimRun threaded = runOn(kBlackoutName, options, RunMode::kFused, false);
  const RunResult& r = det1.result;
  ASSERT_TRUE(r.accuracy);
  printFigures("fused, blackout", r);

  // The detection module: LiDAR from the first black frame, saying why ...
  const double b0 = options.start_time + kBlackoutBegin, b1 = options.start_time + kBlackoutEnd;
  for (const SwitchEvent& e : r.output.switches) std::printf("[ figures  ] switch t=%.3f -> %s: %s\n",
                                                             e.t - options.start_time,
                                                             e.to == OutputSource::kVisual ? "visual" : "lidar",
                                                             e.reason.c_str());
  // The scenario's premise: vision is the output when the images go black.
  const std::vector<FrameOutput> frames = lvslam::testing::vectorOf(r.records.online);
  const auto before = std::find_if(frames.rbegin(), frames.rend(),
                                   [&](const FrameOutput& f) { return f.t < b0; });
  ASSERT_NE(before, frames.rend());
  ASSERT_EQ(before->source, OutputSource::kVisual) << "vision is not in use before the blackout";
  const auto to_lidar = std::find_if(r.output.switches.begin(), r.output.switches.end(),
                                     [&](const SwitchEvent& e) { return e.to == OutputSource::kLidar && e.t >= b0; });
  ASSERT_NE(to_lidar, r.output.switches.end()) << "no switch to the LiDAR at the blackout";
  EXPECT_LE(to_lidar->t, b0 + 1.0 / 15.0 + 1e-6);  // the first black image (15 Hz)
  EXPECT_NE(to_lidar->reason.find("dark"), std::string::npos) << to_lidar->reason;
  // ... LiDAR throughout the blackout, every frame posed ...
  for (const FrameOutput& f : frames) {
    EXPECT_TRUE(f.T_world_camera.has_value()) << f.t - options.start_time;
    if (f.t >= b0 && f.t <= b1) {
      EXPECT_EQ(f.source, OutputSource::kLidar) << f.t - options.start_time;
    }
  }
  // ... and back to vision (a new map) within 3 s after it.
  const auto to_visual = std::find_if(to_lidar, r.output.switches.end(),
                                      [](const SwitchEvent& e) { return e.to == OutputSource::kVisual; });
  ASSERT_NE(to_visual, r.output.switches.end()) << "vision never came back";
  EXPECT_GT(to_visual->t, b1);
  EXPECT_LT(to_visual->t, b1 + 3.0);
  EXPECT_EQ(r.summary.visual_maps, 2u);

  // Continuous: at every switch each output step is the true step up to a
  // few mm (a jump would be the offset between the visual map and the
  // LiDAR's output, from centimetres to metres for a new map). Elsewhere the
  // visual estimate's jitter is below 2 cm per step (a frame moves up to
  // 2.7 cm), and where the LiDAR is the output no step is worse than the
  // LiDAR's own worst (its sweep-to-sweep corrections, 2-4 cm here).
  ASSERT_EQ(r.output.trajectory.size(), frames.size());
  const std::vector<double> errors = stepErrors(r.output.trajectory, det1.ground_truth);
  const SimRun lidar = runOn(kBlackoutName, options, RunMode::kLidar, true);
  const std::vector<double> lidar_errors = stepErrors(lidar.result.output.trajectory, lidar.ground_truth);
  const double lidar_worst = *std::max_element(lidar_errors.begin(), lidar_errors.end());
  double worst = 0.0, worst_lidar_sourced = 0.0;
  for (std::size_t k = 1; k < r.output.trajectory.size(); ++k) {
    const bool from_lidar = frames[k].source == OutputSource::kLidar;
    (from_lidar ? worst_lidar_sourced : worst) = std::max(from_lidar ? worst_lidar_sourced : worst, errors[k - 1]);
  }
  std::printf("[ figures  ] largest step error %.4f m (vision the output), %.4f m (LiDAR; LiDAR alone %.4f m)\n",
              worst, worst_lidar_sourced, lidar_worst);
  for (const SwitchEvent& e : r.output.switches) {
    const auto at = std::find_if(r.output.trajectory.begin(), r.output.trajectory.end(),
                                 [&](const StampedPose& p) { return p.t == e.t; });
    ASSERT_NE(at, r.output.trajectory.end());
    const std::size_t k = static_cast<std::size_t>(at - r.output.trajectory.begin());
    ASSERT_GT(k, 0u);
    std::printf("[ figures  ] step error at the switch t=%.3f: %.4f m\n", e.t - options.start_time, errors[k - 1]);
    EXPECT_LT(errors[k - 1], 0.01) << e.t - options.start_time;
  }
  EXPECT_LT(worst, 0.02);
  EXPECT_LE(worst_lidar_sourced, lidar_worst);
  // Fused must beat the LiDAR alone, which errs about 1 cm on these frames.
  EXPECT_LT(r.accuracy->ate.stats.rmse, 0.01);

  // Deterministic twice: the same files byte for byte.
  lvslam::testing::TempDir dir;
  const auto write = [&](const char* name, const RunResult& run) {
    writeRunOutputs(dir.file(name), run.records, run.output, run.summary, {run.accuracy, run.accuracy_refined}, false);
  };
  write("det1", det1.result);
  write("det2", det2.result);
  write("threaded", threaded.result);
  for (const char* file : {"trajectory.tum", "stats.json", "map.ply", "lines.ply", "subsystems/visual_map_0.tum",
                           "subsystems/lidar_camera.tum"}) {
    const std::string reference = fileText(dir.path() / "det1" / file);
    EXPECT_FALSE(reference.empty()) << file;
    EXPECT_TRUE(reference == fileText(dir.path() / "det2" / file)) << file << " differs between deterministic runs";
    // The threads change when things run, never what is computed.
    EXPECT_TRUE(reference == fileText(dir.path() / "threaded" / file)) << file << " differs in the threaded run";
  }
  // The same poses, bit for bit, in memory too.
  const Trajectory& a = det1.result.output.trajectory;
  const Trajectory& b = threaded.result.output.trajectory;
  ASSERT_EQ(a.size(), b.size());
  double largest = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].t, b[k].t);
    largest = std::max(largest, (a[k].T_world_frame.matrix() - b[k].T_world_frame.matrix()).cwiseAbs().maxCoeff());
  }
  EXPECT_EQ(largest, 0.0) << "threaded and deterministic trajectories differ";
}

}  // namespace
}  // namespace lvslam::system
