// `lvslam simulate`: writes a simulated M2DGR-like sequence folder.
#include <iostream>
#include <memory>
#include <string>

#include "command.h"
#include "lvslam/sim/simulate_sequence.h"

namespace lvslam::apps {

namespace {

struct SimulateArgs {
  sim::SimOptions options;
  std::string out_dir;
  std::string extrinsic_error;
  std::string camera_blackout;
  bool blur = false;
};

int runSimulate(SimulateArgs args) {
  if (!args.extrinsic_error.empty()) args.options.extrinsic_error = sim::parseExtrinsicError(args.extrinsic_error);
  if (!args.camera_blackout.empty())
    args.options.camera_blackout = sim::parseTimeInterval(args.camera_blackout, "--camera-blackout");
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
      "Write a simulated sequence folder (camera 640x480 at 15 Hz, 32-ring LiDAR at 10 Hz, ground truth at "
      "200 Hz) of an M2DGR-like scene. See docs/simulator.md.");
  auto args = std::make_shared<SimulateArgs>();
  cmd->add_option("--scenario", args->options.scenario, "room (office), hall (large hall) or gate (outdoors)")
      ->default_val("room");
  cmd->add_option("--out", args->out_dir, "Folder to write")->required();
  cmd->add_option("--duration", args->options.duration, "Seconds of recording")->default_val(60.0);
  cmd->add_option("--seed", args->options.seed, "Random seed (same seed, same bytes)")->default_val(1);
  cmd->add_flag("--night", args->options.night, "Dark scene, noisy camera (lamps lit outdoors)");
  cmd->add_flag("--blur", args->blur, "Motion blur from sub-exposures (always on for hall)");
  cmd->add_flag("--distortion", args->options.distortion, "Render and write radtan lens distortion");
  cmd->add_flag("--person", args->options.walking_person, "A person (a moving box) walks through the scene");
  cmd->add_option("--extrinsic-error", args->extrinsic_error,
                  "DEG,M: write T_camera_lidar rotated DEG degrees and shifted M metres off the truth "
                  "(the truth goes into extrinsics_truth.yaml)");
  cmd->add_option("--camera-blackout", args->camera_blackout,
                  "T0,T1: black images between these seconds from the sequence start");
  cmd->callback([&action, args] { action = [args] { return runSimulate(*args); }; });
}

}  // namespace lvslam::apps
