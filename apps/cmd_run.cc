// `lvslam run`: runs a SLAM mode over a recording (a sequence folder, or ROS1
// bags with a sensor preset), writes its trajectory and, when there is ground
// truth, prints the accuracy.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>
#include <cmath>
#include <ctime>
#include <memory>
#include <set>
#include <string>

#include <fmt/format.h>

#include "command.h"
#include "lvslam/core/error.h"
#include "lvslam/core/yaml_config.h"
#include "lvslam/eval/eval_report.h"
#include "lvslam/eval/evaluate.h"
#include "lvslam/io/recording.h"
#include "lvslam/io/tum.h"
#include "lvslam/lidar/lidar_odometry.h"
#include "lvslam/sim/simulate_sequence.h"
#include "lvslam/visual/tracking/visual_slam.h"

namespace lvslam::apps {

namespace {

struct RunArgs {
  RecordingRequest input;
  std::string mode = "lidar";
  std::string out_dir;
  std::string config_path;
};

// What a mode hands back: the sensor trajectories it estimated.
struct RunOutput {
  Trajectory T_world_lidar;
  Trajectory T_world_camera;  // visual mode
  std::string summary;
  bool metric = false;  // visual mode: scale from LiDAR depth hints
};

RunOutput runLidarMode(Recording& recording, const RunArgs& args) {
  if (!recording.source->hasLidar()) throw Error(recording.name, "mode lidar needs a recording with a LiDAR");
  const lidar::LidarOdometryConfig config =
      args.config_path.empty() ? lidar::LidarOdometryConfig{}
                               : lidar::loadLidarOdometryConfig(YamlConfig::loadFile(args.config_path));
  lidar::LidarOdometry odometry(config);
  RunOutput output;
  std::map<std::string, int> statuses;
  std::size_t scans = 0;
  const auto start = std::chrono::steady_clock::now();
  while (auto data = recording.source->next()) {
    const auto* scan = std::get_if<LidarScan>(&*data);
    if (!scan) continue;  // images are not used in this mode
    const lidar::OdometryResult result = odometry.process(*scan);
    ++scans;
    ++statuses[lidar::statusName(result.status)];
    if (result.status != lidar::OdometryStatus::kRejected)
      output.T_world_lidar.push_back({result.timestamp, result.T_world_lidar});
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  output.summary = fmt::format("lidar odometry: {} scans in {:.2f} s ({:.1f} scans/s, including reading)", scans,
                               seconds, static_cast<double>(scans) / std::max(seconds, 1e-9));
  for (const auto& [name, count] : statuses) output.summary += fmt::format("; {} {}", name, count);
  return output;
}

// Visual mode: depth hints for a metric start from the LiDAR points measured
// closest in time to the image (|dt| <= max_dt), projected through
// T_camera_lidar. The robot moves during a sweep; only points near the
// image time keep the hint error small.
std::vector<visual::PixelDepth> lidarDepthHints(const std::vector<LidarScan>& scans, double t_image,
                                                const Calibration& calibration, double max_dt) {
  std::vector<visual::PixelDepth> hints;
  const PinholeCamera& camera = *calibration.camera;
  for (const LidarScan& scan : scans) {
    for (std::size_t i = 0; i < scan.size(); ++i) {
      if (std::abs(scan.pointTime(i) - t_image) > max_dt) continue;
      const Eigen::Vector3d p_camera = calibration.T_camera_lidar * scan.points[i].p.cast<double>();
      if (!(p_camera.z() > 0.3)) continue;
      const auto pixel = camera.project(p_camera);
      if (pixel && camera.inImage(*pixel)) hints.push_back({*pixel, p_camera.z()});
    }
  }
  return hints;
}

RunOutput runVisualMode(Recording& recording, const RunArgs& args) {
  if (!recording.source->hasCamera()) throw Error(recording.name, "mode visual needs a recording with a camera");
  const Calibration calibration = recording.source->calibration();
  visual::VisualSlamConfig config;
  if (!args.config_path.empty()) {
    const YamlConfig root = YamlConfig::loadFile(args.config_path);
    if (const auto section = root.find("visual")) config.visual = visual::loadVisualConfig(*section);
  }
  visual::VisualSlam slam(config, *calibration.camera);
  RunOutput output;
  std::vector<LidarScan> recent_scans;  // the last two, bracketing the image time
  std::map<std::string, int> states;
  std::size_t frames = 0, tracked = 0, keyframes = 0;
  std::set<int> maps;
  // A new map (after a loss) is anchored at the last tracked pose: the camera
  // is assumed not to have moved while lost (no relocalisation across maps).
  Eigen::Isometry3d T_out_map = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T_out_last = Eigen::Isometry3d::Identity();
  int anchored_map = 0;
  double cpu_seconds = 0.0;
  const auto start = std::chrono::steady_clock::now();
  while (auto data = recording.source->next()) {
    if (const auto* scan = std::get_if<LidarScan>(&*data)) {
      recent_scans.push_back(*scan);
      if (recent_scans.size() > 2) recent_scans.erase(recent_scans.begin());
      continue;
    }
    const auto& image = std::get<ImageFrame>(*data);
    if (slam.needsDepthHints() && recording.source->hasLidar())
      slam.setDepthHints(lidarDepthHints(recent_scans, image.timestamp, calibration, 0.02));
    const std::clock_t cpu0 = std::clock();
    const visual::VisualFrameResult result = slam.track(image);
    cpu_seconds += static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
    ++frames;
    ++states[visual::trackingStateName(result.state)];
    if (!result.pose_valid) continue;
    if (result.map_id != anchored_map) {
      const Eigen::Isometry3d T_map_first =
          result.initial_reference ? result.initial_reference->T_world_frame : result.T_world_camera;
      T_out_map = T_out_last * T_map_first.inverse();
      anchored_map = result.map_id;
    }
    if (result.initial_reference)
      output.T_world_camera.push_back({result.initial_reference->t, T_out_map * result.initial_reference->T_world_frame});
    output.T_world_camera.push_back({result.timestamp, T_out_map * result.T_world_camera});
    T_out_last = output.T_world_camera.back().T_world_frame;
    output.metric = result.metric;
    maps.insert(result.map_id);
    tracked += 1 + (result.initial_reference ? 1 : 0);
    keyframes += result.keyframe ? 1 : 0;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  output.summary = fmt::format(
      "visual slam: {} frames in {:.2f} s ({:.1f} frames/s, including reading); CPU {:.1f} ms/frame in tracking; "
      "tracked {} of {} frames ({:.1f} %); {} keyframes; {} map(s); scale {}",
      frames, seconds, static_cast<double>(frames) / std::max(seconds, 1e-9),
      1000.0 * cpu_seconds / std::max<std::size_t>(frames, 1), tracked, frames,
      100.0 * static_cast<double>(tracked) / std::max<std::size_t>(frames, 1), keyframes, maps.size(),
      output.metric ? "metric (LiDAR depth hints)" : "arbitrary (monocular)");
  for (const auto& [name, count] : states) output.summary += fmt::format("; {} {}", name, count);
  return output;
}

Trajectory transformed(const Trajectory& trajectory, const Eigen::Isometry3d& T_frame_other) {
  Trajectory out = trajectory;
  for (StampedPose& pose : out) pose.T_world_frame = pose.T_world_frame * T_frame_other;
  return out;
}

void printAccuracy(const Recording& recording, const Trajectory& T_world_lidar) {
  if (!recording.ground_truth) return;
  const bool gt_is_camera = recording.ground_truth_frame == GroundTruthFrame::kCamera;
  // Compare like with like: the estimate in the frame the ground truth gives.
  const Eigen::Isometry3d T_lidar_camera = recording.source->calibration().T_camera_lidar.inverse();
  const Trajectory estimate = gt_is_camera ? transformed(T_world_lidar, T_lidar_camera) : T_world_lidar;
  eval::EvalOptions options;
  options.gt_name = recording.ground_truth_path;
  options.est_name = gt_is_camera ? "estimate (camera frame)" : "estimate (lidar frame)";
  std::cout << eval::formatSummary(eval::evaluate(*recording.ground_truth, estimate, options));
}

// The built-in default input: a simulated room sequence, generated once into
// a folder beside the outputs (renamed into place only when complete, so an
// interrupted run never leaves a half sequence that looks whole).
std::string defaultSequence() {
  const std::filesystem::path dir = "out/default-room";
  if (std::filesystem::exists(dir / "sequence.yaml")) return dir.string();
  sim::SimOptions options;
  options.scenario = "room";
  options.duration = 30.0;
  std::cout << "no --sequence or --bag given: simulating the built-in default, a " << options.duration
            << " s room sequence, into " << dir.string() << " (once)\n";
  const std::filesystem::path partial = dir.string() + ".partial";
  std::filesystem::remove_all(partial);
  sim::simulateSequence(options, partial.string());
  std::filesystem::rename(partial, dir);
  return dir.string();
}

// Visual mode output: T_world_camera at each tracked image; the accuracy
// with SE3 alignment when the scale is metric, Sim3 otherwise.
int runVisual(Recording& recording, const RunArgs& args) {
  const RunOutput output = runVisualMode(recording, args);
  std::filesystem::create_directories(args.out_dir);
  const std::string path = (std::filesystem::path(args.out_dir) / "trajectory.tum").string();
  writeTum(path, output.T_world_camera);
  std::cout << output.summary << "\n"
            << "wrote " << path << " (T_world_camera, " << output.T_world_camera.size() << " poses)\n";
  if (!recording.ground_truth || output.T_world_camera.size() < eval::kMinAssociatedPairs) return 0;
  const bool gt_is_camera = recording.ground_truth_frame == GroundTruthFrame::kCamera;
  const Eigen::Isometry3d T_camera_lidar = recording.source->calibration().T_camera_lidar;
  const Trajectory estimate = gt_is_camera ? output.T_world_camera : transformed(output.T_world_camera, T_camera_lidar);
  eval::EvalOptions options;
  options.alignment = output.metric ? eval::Alignment::kSE3 : eval::Alignment::kSim3;
  options.gt_name = recording.ground_truth_path;
  options.est_name = gt_is_camera ? "estimate (camera frame)" : "estimate (lidar frame)";
  std::cout << eval::formatSummary(eval::evaluate(*recording.ground_truth, estimate, options));
  return 0;
}

int runRun(RunArgs args) {
  if (args.input.sequence_dir.empty() && args.input.bag_files.empty()) args.input.sequence_dir = defaultSequence();
  Recording recording = openRecording(args.input);
  if (args.mode == "visual") return runVisual(recording, args);
  if (args.mode != "lidar")
    throw Error("lvslam run", "mode '" + args.mode + "' is not yet available (available: lidar, visual)");
  const RunOutput output = runLidarMode(recording, args);
  std::filesystem::create_directories(args.out_dir);
  // With a camera the trajectory is the camera's (docs/sequence-format.md).
  const bool has_camera = recording.source->hasCamera();
  const Trajectory written =
      has_camera ? transformed(output.T_world_lidar, recording.source->calibration().T_camera_lidar.inverse())
                 : output.T_world_lidar;
  const std::string path = (std::filesystem::path(args.out_dir) / "trajectory.tum").string();
  writeTum(path, written);
  std::cout << output.summary << "\n"
            << "wrote " << path << " (" << (has_camera ? "T_world_camera" : "T_world_lidar") << ", "
            << written.size() << " poses)\n";
  printAccuracy(recording, output.T_world_lidar);
  return 0;
}

}  // namespace

void addRunCommand(CLI::App& app, CommandAction& action) {
  CLI::App* cmd = app.add_subcommand(
      "run", "Run SLAM over a sequence folder or ROS1 bags; writes OUT/trajectory.tum and prints the accuracy "
             "when there is ground truth. Without --sequence or --bag it runs on the built-in default, a simulated "
             "room sequence generated once into out/default-room.");
  auto args = std::make_shared<RunArgs>();
  auto* sequence = cmd->add_option("--sequence", args->input.sequence_dir, "Sequence folder (docs/sequence-format.md)");
  auto* bags = cmd->add_option("--bag", args->input.bag_files, "ROS1 bag files of one recording (needs --preset)");
  sequence->excludes(bags);
  cmd->add_option("--preset", args->input.preset, "Sensor preset for bags: a name in config/ (m2dgr) or a file");
  cmd->add_option("--lidar-topic", args->input.lidar_topic, "LiDAR topic of the bags (overrides the preset)");
  cmd->add_option("--camera-topic", args->input.camera_topic, "Camera topic of the bags (overrides the preset)");
  cmd->add_option("--groundtruth", args->input.groundtruth_file, "TUM ground truth for bags (frame from the preset)");
  cmd->add_option("--mode", args->mode, "lidar (LiDAR odometry only), visual (monocular point-line SLAM, metric start from LiDAR depth when "
                 "there is a LiDAR); fused: not yet available")
      ->default_val("lidar")
      ->check(CLI::IsMember({"lidar", "visual", "fused"}));
  cmd->add_option("--out", args->out_dir, "Output folder")->default_val("out/run");
  cmd->add_option("--config", args->config_path, "YAML configuration (e.g. config/sim.yaml); defaults otherwise");
  cmd->callback([&action, args] { action = [args] { return runRun(*args); }; });
}

}  // namespace lvslam::apps
