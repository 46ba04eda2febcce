// `lvslam simulate`: writes a simulated M2DGR-like sequence folder.
#include <iostream>
#include <memory>
#include <string>

#include "command.h"
#include "lvslam/core/error.h"
#include "lvslam/sim/families.h"
#include "lvslam/sim/simulate_sequence.h"

namespace lvslam::apps {

namespace {

struct SimulateArgs {
  sim::SimOptions options;
  std::string family;
  std::string out_dir;
  std::string extrinsic_error;
  std::string camera_blackout;
  std::string lidar_dropout;
  bool blur = false;
};

// A family preset with the duration and seed given beside it (and the
// extrinsic error, blackout and drop-out, applied after).
sim::SimOptions familyWith(const SimulateArgs& args, const CLI::App& cmd) {
  for (const char* other : {"--scenario", "--night", "--blur", "--distortion", "--person", "--people", "--lidar",
                            "--beam-footprint", "--auto-exposure", "--rolling-shutter", "--speed-scale",
                            "--exposure-scale"})
    if (cmd.count(other) > 0) throw Error("--family", std::string("a family sets its own options; drop ") + other);
  sim::SimOptions options = sim::familyOptions(args.family);
  options.duration = args.options.duration;
  options.seed = args.options.seed;
  return options;
}

int runSimulate(SimulateArgs args, const CLI::App& cmd) {
  if (!args.family.empty()) args.options = familyWith(args, cmd);
  if (!args.extrinsic_error.empty()) args.options.extrinsic_error = sim::parseExtrinsicError(args.extrinsic_error);
  if (!args.camera_blackout.empty())
    args.options.camera_blackout = sim::parseTimeInterval(args.camera_blackout, "--camera-blackout");
  if (!args.lidar_dropout.empty())
    args.options.lidar_dropout = sim::parseTimeInterval(args.lidar_dropout, "--lidar-dropout");
  if (args.blur) args.options.blur = true;
  const sim::SimulationSummary summary = sim::simulateSequence(args.options, args.out_dir);
  std::cout << "wrote " << args.out_dir << ": " << summary.images << " images, " << summary.scans << " scans, "
            << summary.groundtruth_poses << " ground-truth poses\n";
  return 0;
}

}  // namespace

void addSimulateCommand(CLI::App& app, CommandAction& action) {
  CLI::App* cmd = app.add_subcommand(
      "simulate",
      "Write a simulated sequence folder (camera 640x480 at 15 Hz, 32- or 16-ring LiDAR at 10 Hz, ground truth at "
      "200 Hz) of an M2DGR-like scene or a family preset. See docs/simulator.md.");
  auto args = std::make_shared<SimulateArgs>();
  cmd->add_option("--scenario", args->options.scenario,
                  "room (office), hall (large hall), gate (outdoors), corridor, yard, office (plain), atrium (glass) "
                  "or twins (two identical rooms on a corridor)")
      ->default_val("room");
  std::string families;
  for (const auto& name : sim::familyNames()) families += (families.empty() ? "" : ", ") + name;
  cmd->add_option("--family", args->family,
                  "A named preset of scene and options (" + families + "); --duration and --seed still apply");
  cmd->add_option("--out", args->out_dir, "Folder to write")->required();
  cmd->add_option("--duration", args->options.duration, "Seconds of recording")->default_val(60.0);
  cmd->add_option("--seed", args->options.seed, "Random seed (same seed, same bytes)")->default_val(1);
  cmd->add_flag("--night", args->options.night, "Dark scene, noisy camera (lamps lit outdoors)");
  cmd->add_flag("--blur", args->blur, "Motion blur from sub-exposures (always on for hall)");
  cmd->add_flag("--distortion", args->options.distortion, "Render and write radtan lens distortion");
  cmd->add_flag("--person", args->options.walking_person, "A person (a moving box) walks through the scene");
  cmd->add_option("--people", args->options.people, "People walking on their own paths (hall only for more than one)");
  cmd->add_option("--lidar", args->options.lidar, "vlp32c (32 rings) or vlp16 (16 rings, -15..+15 deg)");
  cmd->add_flag("--beam-footprint", args->options.beam_footprint,
                "LiDAR pulses with a footprint (mixed returns at depth edges) and range noise growing with range "
                "and incidence");
  cmd->add_flag("--auto-exposure", args->options.auto_exposure, "Exposure follows the scene's brightness, with a lag");
  cmd->add_flag("--rolling-shutter", args->options.rolling_shutter, "Each image row exposed at its own time");
  cmd->add_option("--speed-scale", args->options.speed_scale, "Multiplies the robot's speed, turn rate, acceleration");
  cmd->add_option("--exposure-scale", args->options.exposure_scale, "Multiplies the exposure time (motion blur)");
  cmd->add_option("--extrinsic-error", args->extrinsic_error,
                  "DEG,M: write T_camera_lidar rotated DEG degrees and shifted M metres off the truth "
                  "(the truth goes into extrinsics_truth.yaml)");
  cmd->add_option("--camera-blackout", args->camera_blackout,
                  "T0,T1: black images between these seconds from the sequence start");
  cmd->add_option("--lidar-dropout", args->lidar_dropout,
                  "T0,T1: no LiDAR sweep that starts between these seconds from the sequence start");
  cmd->callback([&action, args, cmd] { action = [args, cmd] { return runSimulate(*args, *cmd); }; });
}

}  // namespace lvslam::apps
