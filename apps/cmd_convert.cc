// `lvslam convert`: recordings of other formats to a sequence folder.
//   convert bag BAG... --lidar-topic T --camera-topic T [--preset m2dgr|FILE] [--groundtruth FILE] --out DIR
//   convert bag --list BAG...
//   convert kitti-raw --drive DIR --calib DIR [--camera 0|2] --out DIR
//   convert to-bag --sequence DIR --out BAG [--lidar-topic T] [--camera-topic T] [--image-format raw|png|jpeg]
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "command.h"
#include "lvslam/core/error.h"
#include "lvslam/io/kitti_raw_convert.h"
#include "lvslam/io/sensor_preset.h"
#ifdef LVSLAM_HAS_ROSBAG
#include "lvslam/io/rosbag_convert.h"
#include "lvslam/io/rosbag_reader.h"
#endif
#include "lvslam/io/sequence_to_bag.h"  // declarations only; defined with the ROS bag component

namespace lvslam::apps {

namespace {

struct BagArgs {
  std::vector<std::string> bags;
  bool list = false;
  std::string lidar_topic, camera_topic, preset, groundtruth, out, name;
  std::optional<GroundTruthFrame> groundtruth_frame;
};

const std::map<std::string, GroundTruthFrame> kFrames{{"camera", GroundTruthFrame::kCamera},
                                                      {"lidar", GroundTruthFrame::kLidar}};

#ifdef LVSLAM_HAS_ROSBAG
int listBags(const BagArgs& args) {
  for (const std::string& bag : args.bags) {
    const RosbagReader reader(bag);
    std::cout << bag << (reader.damage().empty() ? "" : "  (damaged: " + reader.damage() + ")") << "\n";
    for (const BagTopicInfo& t : reader.topics())
      std::cout << fmt::format("  {:<40} {:<32} {:>8}\n", t.topic, t.type, t.messages);
  }
  return 0;
}

int runBag(const BagArgs& args) {
  if (args.list) return listBags(args);
  if (args.out.empty()) throw Error("lvslam convert bag", "--out DIR is required (or --list)");
  BagConvertOptions options;
  options.bags = args.bags;
  options.lidar_topic = args.lidar_topic;
  options.camera_topic = args.camera_topic;
  if (!args.preset.empty()) options.preset = loadSensorPreset(findSensorPreset(args.preset));
  options.groundtruth_path = args.groundtruth;
  options.groundtruth_frame = args.groundtruth_frame;
  options.out_dir = args.out;
  options.name = args.name;
  const BagConvertStats s = convertBags(options);
  std::cout << fmt::format("{}: {} images, {} scans ({} points), {} ground-truth poses; {} messages skipped\n",
                           args.out, s.images, s.scans, s.points, s.groundtruth, s.skipped);
  return 0;
}

int runToBag(const SequenceToBagOptions& options) {
  const SequenceToBagStats s = writeSequenceBag(options);
  std::cout << fmt::format("{}: {} images on {}, {} scans ({} points) on {}; preset {}\n", options.bag_path, s.images,
                           cameraTopicOf(options), s.scans, s.points, options.lidar_topic, s.preset_path);
  return 0;
}
#else
[[noreturn]] void withoutRosbag(const std::string& command) {
  throw Error(command, "this lvslam was built without ROS bag support (-DLVSLAM_WITH_ROSBAG=OFF); "
                       "run scripts/install-deps.sh and rebuild with it ON");
}
int runBag(const BagArgs&) { withoutRosbag("lvslam convert bag"); }
int runToBag(const SequenceToBagOptions&) { withoutRosbag("lvslam convert to-bag"); }
#endif

void addBagCommand(CLI::App& convert, CommandAction& action) {
  CLI::App* cmd = convert.add_subcommand("bag", "ROS1 bags of one recording (several files in any order) to a sequence folder");
  auto args = std::make_shared<BagArgs>();
  cmd->add_option("bags", args->bags, "Bag files")->required()->check(CLI::ExistingFile);
  cmd->add_flag("--list", args->list, "List each bag's topics with types and message counts, and stop");
  cmd->add_option("--lidar-topic", args->lidar_topic, "sensor_msgs/PointCloud2 topic (default: the preset's)");
  cmd->add_option("--camera-topic", args->camera_topic,
                  "sensor_msgs/Image or sensor_msgs/CompressedImage topic (default: the preset's)");
  cmd->add_option("--preset", args->preset, "Sensor preset: a name in config/ (m2dgr) or a YAML file");
  cmd->add_option("--groundtruth", args->groundtruth, "Ground truth (TUM) to copy into the folder")
      ->check(CLI::ExistingFile);
  cmd->add_option("--groundtruth-frame", args->groundtruth_frame,
                  "Sensor whose pose the ground truth gives: camera or lidar (default: the preset's)")
      ->transform(CLI::CheckedTransformer(kFrames, CLI::ignore_case));
  cmd->add_option("--out", args->out, "Sequence folder to write");
  cmd->add_option("--name", args->name, "Sequence name (default: the folder's name)");
  cmd->callback([&action, args] { action = [args] { return runBag(*args); }; });
}

void addKittiRawCommand(CLI::App& convert, CommandAction& action) {
  CLI::App* cmd = convert.add_subcommand(
      "kitti-raw", "A KITTI raw synced drive (rectified images, Velodyne scans, OXTS ground truth) to a sequence folder");
  auto options = std::make_shared<KittiRawConvertOptions>();
  cmd->add_option("--drive", options->drive_dir, "Drive folder, e.g. 2011_09_26/2011_09_26_drive_0001_sync")
      ->required()->check(CLI::ExistingDirectory);
  cmd->add_option("--calib", options->calib_dir, "Folder of calib_cam_to_cam.txt, calib_velo_to_cam.txt, "
                                                 "calib_imu_to_velo.txt (e.g. 2011_09_26)")
      ->required()->check(CLI::ExistingDirectory);
  cmd->add_option("--camera", options->camera, "0: left gray camera, 2: left colour camera")
      ->default_val(0)->check(CLI::IsMember({0, 2}));
  cmd->add_option("--groundtruth-frame", options->groundtruth_frame, "Frame of the written ground truth: lidar or camera")
      ->transform(CLI::CheckedTransformer(kFrames, CLI::ignore_case))->default_str("lidar");
  cmd->add_option("--out", options->out_dir, "Sequence folder to write")->required();
  cmd->add_option("--name", options->name, "Sequence name (default: the drive folder's name)");
  cmd->callback([&action, options] {
    action = [options] {
      const KittiRawConvertStats s = convertKittiRaw(*options);
      std::cout << fmt::format("{}: {} images, {} scans, {} ground-truth poses; {} frames skipped\n",
                               options->out_dir, s.images, s.scans, s.groundtruth, s.skipped);
      return 0;
    };
  });
}

void addToBagCommand(CLI::App& convert, CommandAction& action) {
  CLI::App* cmd = convert.add_subcommand(
      "to-bag", "A sequence folder to a ROS1 bag (PointCloud2 with per-point time, Image), each message recorded "
                "when a live driver would publish it, and beside it BAG_STEM.preset.yaml (the sequence's camera, "
                "extrinsics and the bag's topics): replay any sequence into lvslam_node with rosbag play");
  auto options = std::make_shared<SequenceToBagOptions>();
  cmd->add_option("--sequence", options->sequence_dir, "Sequence folder")->required()->check(CLI::ExistingDirectory);
  cmd->add_option("--out", options->bag_path, "Bag file to write")->required();
  cmd->add_option("--lidar-topic", options->lidar_topic, "PointCloud2 topic")->default_val("/velodyne_points");
  cmd->add_option("--camera-topic", options->camera_topic,
                  "Image topic (default /camera/image_raw, or /camera/image_raw/compressed when compressed)");
  const std::map<std::string, BagImageFormat> formats{
      {"raw", BagImageFormat::kRaw}, {"png", BagImageFormat::kPng}, {"jpeg", BagImageFormat::kJpeg}};
  cmd->add_option("--image-format", options->image_format,
                  "raw (sensor_msgs/Image), png (CompressedImage, lossless) or jpeg (CompressedImage, quality 95)")
      ->transform(CLI::CheckedTransformer(formats, CLI::ignore_case))->default_str("raw");
  cmd->add_option("--lidar-frame", options->lidar_frame, "frame_id of the scans")->default_val("velodyne");
  cmd->add_option("--camera-frame", options->camera_frame, "frame_id of the images")->default_val("camera");
  cmd->callback([&action, options] { action = [options] { return runToBag(*options); }; });
}

}  // namespace

void addConvertCommand(CLI::App& app, CommandAction& action) {
  CLI::App* convert = app.add_subcommand("convert", "Convert recordings (ROS1 bags, KITTI raw) to sequence folders, and sequence folders to ROS1 bags");
  convert->require_subcommand(1);
  addBagCommand(*convert, action);
  addKittiRawCommand(*convert, action);
  addToBagCommand(*convert, action);
}

}  // namespace lvslam::apps
