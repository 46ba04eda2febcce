// `lvslam run`: runs a SLAM mode over a sequence folder, writes its trajectory
// and, when the sequence has ground truth, prints the accuracy.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "command.h"
#include "lvslam/core/error.h"
#include "lvslam/core/yaml_config.h"
#include "lvslam/eval/eval_report.h"
#include "lvslam/eval/evaluate.h"
#include "lvslam/io/sequence_reader.h"
#include "lvslam/io/tum.h"
#include "lvslam/lidar/lidar_odometry.h"

namespace lvslam::apps {

namespace {

struct RunArgs {
  std::string sequence_dir;
  std::string mode = "lidar";
  std::string out_dir;
  std::string config_path;
};

// What a mode hands back: the sensor trajectories it estimated.
struct RunOutput {
  Trajectory T_world_lidar;
  std::string summary;
};

RunOutput runLidarMode(const SequenceReader& reader, const RunArgs& args) {
  if (!reader.hasLidar())
    throw Error(reader.directory() + "/sequence.yaml", "mode lidar needs a sequence with a 'lidar' section");
  const lidar::LidarOdometryConfig config =
      args.config_path.empty() ? lidar::LidarOdometryConfig{}
                               : lidar::loadLidarOdometryConfig(YamlConfig::loadFile(args.config_path));
  lidar::LidarOdometry odometry(config);
  RunOutput output;
  std::map<std::string, int> statuses;
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < reader.lidarFiles().size(); ++i) {
    const lidar::OdometryResult result = odometry.process(reader.loadScan(i));
    ++statuses[lidar::statusName(result.status)];
    if (result.status != lidar::OdometryStatus::kRejected)
      output.T_world_lidar.push_back({result.timestamp, result.T_world_lidar});
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  output.summary = fmt::format("lidar odometry: {} scans in {:.2f} s ({:.1f} scans/s, including reading)",
                               reader.lidarFiles().size(), seconds, reader.lidarFiles().size() / std::max(seconds, 1e-9));
  for (const auto& [name, count] : statuses) output.summary += fmt::format("; {} {}", name, count);
  return output;
}

Trajectory transformed(const Trajectory& trajectory, const Eigen::Isometry3d& T_frame_other) {
  Trajectory out = trajectory;
  for (StampedPose& pose : out) pose.T_world_frame = pose.T_world_frame * T_frame_other;
  return out;
}

void printAccuracy(const SequenceReader& reader, const Trajectory& T_world_lidar) {
  if (!reader.hasGroundTruth()) return;
  const SequenceInfo& info = reader.info();
  const bool gt_is_camera = info.groundtruth_frame.value_or(GroundTruthFrame::kCamera) == GroundTruthFrame::kCamera;
  // Compare like with like: the estimate in the frame the ground truth gives.
  const Trajectory estimate =
      gt_is_camera ? transformed(T_world_lidar, info.T_camera_lidar.inverse()) : T_world_lidar;
  eval::EvalOptions options;
  options.gt_name = reader.directory() + "/groundtruth.txt";
  options.est_name = gt_is_camera ? "estimate (camera frame)" : "estimate (lidar frame)";
  std::cout << eval::formatSummary(eval::evaluate(reader.groundTruth(), estimate, options));
}

int runRun(const RunArgs& args) {
  const SequenceReader reader(args.sequence_dir);
  if (args.mode != "lidar")
    throw Error("lvslam run", "mode '" + args.mode + "' is not yet available (available: lidar)");
  const RunOutput output = runLidarMode(reader, args);
  std::filesystem::create_directories(args.out_dir);
  // With a camera the trajectory is the camera's (docs/sequence-format.md).
  const Trajectory written = reader.hasCamera()
                                 ? transformed(output.T_world_lidar, reader.info().T_camera_lidar.inverse())
                                 : output.T_world_lidar;
  const std::string path = (std::filesystem::path(args.out_dir) / "trajectory.tum").string();
  writeTum(path, written);
  std::cout << output.summary << "\n"
            << "wrote " << path << " (" << (reader.hasCamera() ? "T_world_camera" : "T_world_lidar") << ", "
            << written.size() << " poses)\n";
  printAccuracy(reader, output.T_world_lidar);
  return 0;
}

}  // namespace

void addRunCommand(CLI::App& app, CommandAction& action) {
  CLI::App* cmd = app.add_subcommand(
      "run", "Run SLAM over a sequence folder; writes OUT/trajectory.tum and prints the accuracy when the "
             "sequence has ground truth.");
  auto args = std::make_shared<RunArgs>();
  cmd->add_option("--sequence", args->sequence_dir, "Sequence folder (docs/sequence-format.md)")->required();
  cmd->add_option("--mode", args->mode, "lidar (LiDAR odometry only); visual and fused: not yet available")
      ->default_val("lidar")
      ->check(CLI::IsMember({"lidar", "visual", "fused"}));
  cmd->add_option("--out", args->out_dir, "Output folder")->required();
  cmd->add_option("--config", args->config_path, "YAML configuration (e.g. config/sim.yaml); defaults otherwise");
  cmd->callback([&action, args] { action = [args] { return runRun(*args); }; });
}

}  // namespace lvslam::apps
