// `lvslam eval`: accuracy of an estimated trajectory against ground truth.
#include <cctype>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "command.h"
#include "lvslam/core/error.h"
#include "lvslam/eval/eval_report.h"
#include "lvslam/eval/evaluate.h"
#include "lvslam/eval/sensor_frame.h"
#include "lvslam/io/groundtruth_reference.h"
#include "lvslam/io/tum.h"
#include "lvslam/report/eval_report_page.h"

namespace lvslam::apps {

namespace {

struct EvalArgs {
  std::string sequence_dir;  // ground truth, its frame and the extrinsic from a sequence folder
  std::string gt_frame;      // camera | lidar, for --gt
  std::string est_frame;     // camera | lidar; default: what `lvslam run` writes
  std::string extrinsic_path;
  std::string gt_path;
  std::string est_path;
  std::string format = "tum";
  std::string times_path;
  std::string gt_times_path;
  std::string align = "se3";
  std::string rpe_pairs_on = "est";
  eval::EvalOptions options;
  bool json = false;
  std::string report_path;  // --report FILE.html
};

Trajectory readTrajectory(const std::string& path, const std::string& format,
                          const std::string& times_path) {
  if (format == "kitti") return readKittiPoses(path, times_path);
  return readTum(path);
}

std::string toLower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

GroundTruthFrame parseFrame(const std::string& name) {
  return name == "lidar" ? GroundTruthFrame::kLidar : GroundTruthFrame::kCamera;
}

eval::SensorFrame sensorFrame(GroundTruthFrame frame) {
  return frame == GroundTruthFrame::kLidar ? eval::SensorFrame::kLidar : eval::SensorFrame::kCamera;
}

// The ground truth and what is known of its frame: from --sequence, or
// from --gt with --gt-frame and --extrinsic.
GroundTruthReference groundTruthFor(const EvalArgs& args) {
  if (!args.sequence_dir.empty()) return groundTruthOfSequence(args.sequence_dir);
  GroundTruthReference ref;
  ref.path = args.gt_path;
  ref.trajectory = readTrajectory(args.gt_path, args.format, args.gt_times_path.empty() ? args.times_path : args.gt_times_path);
  if (!args.gt_frame.empty()) ref.frame = parseFrame(args.gt_frame);
  if (!args.extrinsic_path.empty()) ref.T_camera_lidar = readExtrinsicFile(args.extrinsic_path);
  return ref;
}

// The estimate in the ground truth's frame (lvslam run's own rule); when the
// frames cannot be told, as it is, with `warning` set (printed once the
// evaluation has succeeded, so that a failing one stays one error line).
Trajectory estimateInGroundTruthFrame(const EvalArgs& args, const GroundTruthReference& ref, const Trajectory& est,
                                      std::string& warning) {
  // Without a word the estimate is what `lvslam run` writes: camera poses.
  const GroundTruthFrame est_frame =
      args.est_frame.empty() ? ref.run_output_frame.value_or(GroundTruthFrame::kCamera) : parseFrame(args.est_frame);
  if (!ref.frame) {
    warning = "lvslam: warning: " + ref.path + ": its sensor frame cannot be told (give --sequence, or "
              "--gt-frame with --extrinsic): compared with the estimate as it is\n";
    return est;
  }
  if (*ref.frame == est_frame) return est;
  if (!ref.T_camera_lidar)
    throw Error("--extrinsic", "needed: the estimate and the ground truth are of different sensors");
  return eval::inSensorFrame(est, sensorFrame(est_frame), sensorFrame(*ref.frame), *ref.T_camera_lidar);
}

// --report needs the page's assets: checked before any work.
std::optional<report::ReportAssets> reportAssets(const EvalArgs& args) {
  if (args.report_path.empty()) return std::nullopt;
  std::string looked_in;
  std::optional<report::ReportAssets> assets = report::loadReportAssets(&looked_in);
  if (!assets) throw Error(args.report_path, "not written: " + report::missingAssetsReason(looked_in));
  return assets;
}

int runEval(const EvalArgs& args) {
  const std::optional<report::ReportAssets> assets = reportAssets(args);
  if (args.format == "tum" && !(args.times_path.empty() && args.gt_times_path.empty()))
    throw Error("lvslam eval", "--times and --gt-times apply to --format kitti only");
  if (args.sequence_dir.empty() == args.gt_path.empty())
    throw Error("lvslam eval", "give either --gt or --sequence");
  const GroundTruthReference ref = groundTruthFor(args);
  std::string frame_warning;
  const Trajectory est =
      estimateInGroundTruthFrame(args, ref, readTrajectory(args.est_path, args.format, args.times_path), frame_warning);
  eval::EvalOptions options = args.options;
  // The option checks already limited these strings to the listed names.
  const std::string align = toLower(args.align);
  options.alignment = align == "sim3"   ? eval::Alignment::kSim3
                      : align == "none" ? eval::Alignment::kNone
                                        : eval::Alignment::kSE3;
  options.rpe_pairs_on =
      toLower(args.rpe_pairs_on) == "gt" ? eval::RpePairsOn::kGroundTruth : eval::RpePairsOn::kEstimate;
  options.gt_name = ref.path;
  options.est_name = args.est_path;
  const eval::EvalResult result = eval::evaluate(ref.trajectory, est, options);
  std::cerr << frame_warning;
  std::cout << (args.json ? eval::formatJson(result) + "\n" : eval::formatSummary(result));
  if (assets) {
    report::writeEvalReport(args.report_path, ref.trajectory, ref.path, est, args.est_path, options.alignment, *assets);
    if (!args.json) std::cout << "wrote " << args.report_path << "\n";
  }
  return 0;
}

}  // namespace

void addEvalCommand(CLI::App& app, CommandAction& action) {
  CLI::App* cmd = app.add_subcommand(
      "eval",
      "Accuracy of an estimated trajectory against ground truth: poses associated by time, "
      "ATE after alignment (evo APE, translation part), RPE (evo, consecutive pairs by path "
      "length, not aligned) and the KITTI odometry metric.");
  // The arguments outlive parsing: the action runs after app.parse returns.
  auto args = std::make_shared<EvalArgs>();
  auto* gt = cmd->add_option("--gt", args->gt_path, "Ground-truth trajectory file");
  auto* sequence = cmd->add_option("--sequence", args->sequence_dir,
                                   "Sequence folder: its groundtruth.txt, in the frame its sequence.yaml names "
                                   "(groundtruth.frame), the estimate moved into that frame by its extrinsic");
  sequence->excludes(gt);
  auto* gt_frame = cmd->add_option("--gt-frame", args->gt_frame, "Sensor frame of --gt: camera or lidar")
                       ->check(CLI::IsMember({"camera", "lidar"}));
  cmd->add_option("--est-frame", args->est_frame,
                  "Sensor frame of the estimate: camera or lidar (default with --sequence: what lvslam run writes, "
                  "the camera's when the sequence has one)")
      ->check(CLI::IsMember({"camera", "lidar"}));
  auto* extrinsic = cmd->add_option("--extrinsic", args->extrinsic_path,
                                    "T_camera_lidar for --gt: a sequence.yaml or a YAML with T_camera_lidar");
  gt_frame->excludes(sequence);
  extrinsic->excludes(sequence);
  cmd->add_option("--est", args->est_path, "Estimated trajectory file")->required();
  cmd->add_option("--align", args->align,
                  "Umeyama alignment of the estimate before ATE: se3 (rotation and translation), "
                  "sim3 (also scale, for monocular), none")
      ->check(CLI::IsMember({"se3", "sim3", "none"}, CLI::ignore_case))
      ->capture_default_str();
  cmd->add_option("--max-dt", args->options.max_dt,
                  "Largest time difference (s) of an associated pose pair")
      ->default_val(0.02)->check(CLI::NonNegativeNumber);
  cmd->add_option("--format", args->format,
                  "File format: tum ('t tx ty tz qx qy qz qw' lines) or kitti (12 numbers, a "
                  "row-major 3x4 [R|t] per line)")
      ->default_val("tum")->check(CLI::IsMember({"tum", "kitti"}));
  cmd->add_option("--times", args->times_path,
                  "kitti format: time stamps of the estimate's poses, one a line (also used for "
                  "the ground truth unless --gt-times is given); without it poses are stamped 0, 1, 2, ...");
  cmd->add_option("--gt-times", args->gt_times_path,
                  "kitti format: time stamps of the ground-truth poses, one a line");
  cmd->add_option("--rpe-delta", args->options.rpe_delta_m,
                  "RPE pair distance: metres of path length between the two poses of a pair")
      ->default_val(10.0)->check(CLI::PositiveNumber);
  cmd->add_option("--rpe-pairs-on", args->rpe_pairs_on,
                  "Whose path length picks the RPE pairs: est (evo's default, reproduces its "
                  "published figures) or gt (evo's --pairs_from_reference)")
      ->check(CLI::IsMember({"est", "gt"}, CLI::ignore_case))
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "Print one JSON object instead of the summary");
  cmd->add_option("--report", args->report_path,
                  "Also write this self-contained HTML page: both trajectories from above and from the side, ATE "
                  "and RPE (1 m, 10 m) over time and their statistics");
  cmd->callback([&action, args] { action = [args] { return runEval(*args); }; });
}

}  // namespace lvslam::apps
