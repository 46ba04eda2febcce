// `lvslam run`: the system over a recording (a sequence folder, or ROS1 bags
// with a sensor preset) in mode fused, lidar or visual; writes OUT/
// trajectory.tum, stats.json, map.ply, lines.ply and report.html and, when
// there is ground truth, groundtruth.tum and prints the accuracy. A recording
// that cannot be read to its end is run up to the fault, its outputs
// written, and the fault then ends the command (exit 2).
#include <chrono>
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "command.h"
#include "progress_line.h"
#include "run_folder.h"
#include "lvslam/io/recording.h"
#include "lvslam/io/tum.h"
#include "lvslam/sim/simulate_sequence.h"
#include "lvslam/system/frame_stats_stream.h"
#include "lvslam/system/run_recording.h"
#include "lvslam/system/output_folder.h"
#include "lvslam/system/saved_map.h"

namespace lvslam::apps {

namespace {

struct RunArgs {
  RecordingRequest input;
  std::string mode = "fused";
  std::string out_dir;
  std::string config_path;
  bool deterministic = false;
  bool realtime = false;
  bool mode_given = false;  // --mode on the command line
  std::vector<std::string> ablations;
  std::string map_in, map_out;
};

// Without --mode the system runs what the recording allows: fused with both
// sensors, else the one subsystem its sensor feeds. A sensor without data
// counts as absent: `--mode fused` then runs the other sensor's mode with a
// warning; a mode whose only sensor has no data has no result (exit 1).
std::string modeFor(const RunArgs& args, const SensorSource& source) {
  const bool camera = source.hasCamera(), lidar = source.hasLidar();
  if (!camera && !lidar) throw std::runtime_error("no result: the recording has neither camera images nor LiDAR scans");
  if (camera && lidar) return args.mode;
  const std::string mode = camera ? "visual" : "lidar";
  const std::string missing = camera ? "LiDAR" : "camera";
  if (args.mode_given && args.mode == mode) return mode;
  if (args.mode_given && args.mode != "fused")
    throw std::runtime_error("no result: mode " + args.mode + " needs " + missing + " data and the recording has none");
  if (args.mode_given)
    std::cerr << "lvslam: warning: the recording has no " << missing << " data: running mode " << mode << " instead of fused\n";
  else
    std::cout << "the recording has no " << missing << ": running mode " << mode << "\n";
  return mode;
}

// The built-in default input: a simulated room sequence, generated once into
// a folder beside the outputs.
std::string defaultSequence() {
  const std::string dir = "out/default-room";
  sim::SimOptions options;
  options.scenario = "room";
  options.duration = 30.0;
  sim::simulateSequenceOnce(options, dir, [&] {
    std::cout << "no --sequence or --bag given: simulating the built-in default, a " << options.duration
              << " s room sequence, into " << dir << " (once)\n";
  });
  return dir;
}

// A saved map is the loop closure's LiDAR keyframes: saving or localising
// needs both. The map file is read, and the file to save to checked, before
// the run, so that a bad one is named now and not after the whole run.
void checkMapsMode(const RunArgs& args, const system::SystemConfig& config) {
  for (const auto& [option, file] : {std::pair{"--map-in", &args.map_in}, std::pair{"--map-out", &args.map_out}})
    if (!file->empty() && config.mode == system::RunMode::kVisual)
      throw Error(option, "a saved map is made of LiDAR keyframes: it needs mode lidar or fused, not visual");
}

void prepareMaps(const RunArgs& args, system::SystemConfig& config) {
  for (const auto& [option, file] : {std::pair{"--map-in", &args.map_in}, std::pair{"--map-out", &args.map_out}})
    if (!file->empty() && !config.loop.enabled)
      throw Error(option, "a saved map is the loop closure's keyframes: it needs loop.enabled: true");
  if (!args.map_in.empty()) {
    system::SavedMap map = system::readSavedMap(args.map_in);
    if (map.keyframes.empty()) throw Error(args.map_in, "the map has no keyframe to localise in");
    config.localize_in = std::make_shared<const std::vector<loop::LoopKeyframe>>(std::move(map.keyframes));
  }
  if (!args.map_out.empty()) {
    // Its folder must take a new file (the map is written beside and renamed
    // over it), and what the name holds now must be a file, not a folder.
    const std::filesystem::path file(args.map_out);
    const std::filesystem::path folder = file.has_parent_path() ? file.parent_path() : ".";
    std::error_code ec;
    if (!std::filesystem::is_directory(folder, ec) || ::access(folder.c_str(), W_OK | X_OK) != 0)
      throw Error(args.map_out, "cannot write the map here: its folder is missing or not writable");
    if (std::filesystem::is_directory(file, ec)) throw Error(args.map_out, "cannot write the map here: it is a folder");
    config.keep_loop_keyframes = true;
  }
}

// After the run folder is written (a map that cannot be written must not
// cost the run's outputs); a run without a LiDAR keyframe has no map.
void writeMapOut(const std::string& path, std::optional<system::SavedMap> map) {
  if (!map) return;
  if (map->keyframes.empty()) {
    std::cerr << "lvslam: warning: --map-out: the run made no LiDAR keyframe, so no map was written to " << path << "\n";
    return;
  }
  system::writeSavedMap(path, *map);
  std::cout << fmt::format("wrote the map {} ({} keyframes, {} lines)\n", path, map->keyframes.size(),
                           map->lines.size());
}

system::SystemConfig loadConfig(const RunArgs& args) {
  system::SystemConfig config = system::loadRunConfig(args.config_path);
  config.mode = system::parseRunMode(args.mode, "--mode");
  config.deterministic = args.deterministic;
  config.realtime = args.realtime;
  for (const std::string& name : args.ablations) system::applyAblation(config, name, "--ablate");
  prepareMaps(args, config);
  return config;
}

int runRun(RunArgs args) {
  if (args.input.sequence_dir.empty() && args.input.bag_files.empty()) args.input.sequence_dir = defaultSequence();
  Recording recording = openRecording(args.input);
  system::SystemConfig config = loadConfig(args);  // a bad option or file is named before --out is touched
  system::prepareOutputFolder(args.out_dir);       // no earlier run's files stay, whatever happens now
  args.mode = modeFor(args, *recording.source);
  config.mode = system::parseRunMode(args.mode, "--mode");
  checkMapsMode(args, config);
  ProgressLine progress;
  const auto start = std::chrono::steady_clock::now();
  std::optional<double> t0;
  const auto showProgress = [&](double t, std::size_t images, std::size_t scans) {
    if (!t0) t0 = t;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    progress.update(fmt::format("[{}] {:.1f} s of data: {} images, {} scans ({:.2f}x real time)", args.mode, t - *t0,
                                images, scans, wall > 0.0 ? (t - *t0) / wall : 0.0));
  };
  // trajectory.tum and stats_frames.jsonl grow frame by frame as the online
  // output makes them (one per camera frame; without a camera the trajectory
  // is the LiDAR's scan trajectory, written at the end), so a killed run
  // leaves what it had.
  std::optional<TumStream> online_poses;
  std::optional<system::FrameStatsStream> frame_stats;
  if (recording.source->hasCamera()) {
    online_poses.emplace(args.out_dir + "/trajectory.tum");
    frame_stats.emplace(args.out_dir + "/stats_frames.jsonl", !args.deterministic);
  }
  system::RunResult run = system::runRecording(recording, config, showProgress, [&](const system::FrameOutput& f) {
    if (online_poses && f.T_world_camera) online_poses->add({f.t, *f.T_world_camera});
    if (frame_stats) frame_stats->add(f);
  });
  online_poses.reset();
  frame_stats.reset();
  progress.finish();
  std::optional<system::SavedMap> map;
  if (!args.map_out.empty() && !run.output.trajectory.empty())
    map = system::savedMapOf(std::move(run.records.loop_keyframes), run.output.loop, run.output.lines_world);
  try {
    finishRunFolder(args.out_dir, recording, std::move(run), args.mode, args.deterministic);
  } catch (...) {  // a fault after the outputs were written: the map too, then the fault
    writeMapOut(args.map_out, std::move(map));
    throw;
  }
  writeMapOut(args.map_out, std::move(map));
  return 0;
}

}  // namespace

void addRunCommand(CLI::App& app, CommandAction& action) {
  CLI::App* cmd = app.add_subcommand(
      "run", "Run SLAM over a sequence folder or ROS1 bags; writes OUT/trajectory.tum (the online output, each "
             "pose from the data up to its frame), trajectory_refined.tum (the offline refinement), stats.json, "
             "map.ply, lines.ply and report.html (one self-contained page of all of it; groundtruth.tum beside it "
             "when there is ground truth), and prints the accuracy of both when there is ground truth. Without --sequence "
             "or --bag it runs on the built-in default, a simulated room sequence generated once into "
             "out/default-room.");
  auto args = std::make_shared<RunArgs>();
  auto* sequence = cmd->add_option("--sequence", args->input.sequence_dir, "Sequence folder (docs/sequence-format.md)");
  auto* bags = cmd->add_option("--bag", args->input.bag_files, "ROS1 bag files of one recording (needs --preset)");
  sequence->excludes(bags);
  cmd->add_option("--preset", args->input.preset, "Sensor preset for bags: a name in config/ (m2dgr) or a file");
  cmd->add_option("--lidar-topic", args->input.lidar_topic, "LiDAR topic of the bags (overrides the preset)");
  cmd->add_option("--camera-topic", args->input.camera_topic, "Camera topic of the bags (overrides the preset)");
  cmd->add_option("--groundtruth", args->input.groundtruth_file, "TUM ground truth for bags (frame from the preset)");
  auto* mode = cmd->add_option("--mode", args->mode,
                  "fused (both subsystems, the fusion framework and the detection module), lidar (LiDAR odometry "
                  "only) or visual (monocular point-line SLAM; with a LiDAR its raw points give metric depth to "
                  "the start and to keyframe points)")
      ->default_val("fused")
      ->check(CLI::IsMember({"lidar", "visual", "fused"}));
  cmd->add_option("--out", args->out_dir, "Output folder")->default_val("out/run");
  cmd->add_option("--config", args->config_path, "YAML configuration (e.g. config/sim.yaml) over config/advanced.yaml, which lists every key with its default");
  cmd->add_option("--ablate", args->ablations,
                  "Switch off one of the paper's contributions (repeatable): direction-residual, "
                  "lidar-direction-refinement, fusion-lines")
      ->check(CLI::IsMember(std::vector<std::string>(std::begin(system::kAblations), std::end(system::kAblations))));
  cmd->add_option("--map-in", args->map_in,
                  "A map saved by an earlier run (--map-out) to localise this run in: its place found by the LiDAR "
                  "keyframes; writes OUT/trajectory_in_map.tum once localised (modes lidar and fused)");
  cmd->add_option("--map-out", args->map_out,
                  "Save this run's map (LiDAR keyframes at their final poses with their features, and the lines) "
                  "to FILE, for a later run's --map-in");
  cmd->add_flag("--realtime", args->realtime,
                "Read the recording at the pace of its time stamps, as a live robot delivers it (the online "
                "output's latency as live); without it the run goes as fast as the machine does");
  cmd->add_flag("--deterministic", args->deterministic,
                "One thread in a fixed order and no wall-clock figures in stats.json: byte-identical output for the "
                "same input");
  cmd->callback([&action, args, mode] {
    args->mode_given = mode->count() > 0;
    action = [args] { return runRun(*args); };
  });
}

}  // namespace lvslam::apps
