#include "lvslam/io/recording.h"

#include <filesystem>

#include "lvslam/core/error.h"
#include "lvslam/io/sensor_preset.h"
#include "lvslam/io/sequence_reader.h"
#include "lvslam/io/tum.h"
#ifdef LVSLAM_HAS_ROSBAG
#include "lvslam/io/rosbag_source.h"
#endif

namespace lvslam {

namespace {

Recording openSequence(const RecordingRequest& request) {
  auto reader = std::make_unique<SequenceReader>(request.sequence_dir);
  Recording rec;
  rec.name = reader->info().name.empty() ? std::filesystem::path(request.sequence_dir).filename().string()
                                         : reader->info().name;
  if (reader->hasGroundTruth()) {
    rec.ground_truth = reader->groundTruth();
    rec.ground_truth_frame = reader->info().groundtruth_frame.value_or(GroundTruthFrame::kCamera);
    rec.ground_truth_path = (std::filesystem::path(request.sequence_dir) / "groundtruth.txt").string();
  }
  rec.source = std::move(reader);
  return rec;
}

Recording openBags(const RecordingRequest& request) {
#ifdef LVSLAM_HAS_ROSBAG
  if (request.preset.empty()) throw Error("--preset", "reading bags needs a sensor preset (e.g. --preset m2dgr)");
  const std::string preset_path = findSensorPreset(request.preset);
  const SensorPreset preset = loadSensorPreset(preset_path);
  BagSourceOptions options;
  options.lidar_topic = request.lidar_topic.empty() ? preset.lidar_topic : request.lidar_topic;
  options.camera_topic = request.camera_topic.empty() ? preset.camera_topic : request.camera_topic;
  if (!options.camera_topic.empty() && !preset.camera)
    throw Error(preset_path, "key 'camera': missing required key (the recording has a camera topic)");
  options.calibration = preset.calibration();
  options.calibration.T_camera_lidar_source = preset_path + ": key 'extrinsics.T_camera_lidar'";
  options.lidar = preset.lidar;
  Recording rec;
  rec.name = std::filesystem::path(request.bag_files.front()).stem().string();
  rec.source = openBagSource(request.bag_files, options);
  if (!request.groundtruth_file.empty()) {
    rec.ground_truth = readTum(request.groundtruth_file);
    rec.ground_truth_frame = preset.groundtruth_frame.value_or(GroundTruthFrame::kLidar);
    rec.ground_truth_path = request.groundtruth_file;
  }
  return rec;
#else
  (void)request;
  throw Error("--bag", "this build has no ROS1 bag support: run scripts/install-deps.sh and rebuild with "
                       "-DLVSLAM_WITH_ROSBAG=ON");
#endif
}

}  // namespace

Recording openRecording(const RecordingRequest& request) {
  const bool has_sequence = !request.sequence_dir.empty();
  const bool has_bags = !request.bag_files.empty();
  if (has_sequence == has_bags) throw Error("--sequence/--bag", "give either a sequence folder or bag files (with --preset)");
  if (!request.groundtruth_file.empty() && has_sequence)
    throw Error("--groundtruth", "a sequence folder brings its own groundtruth.txt");
  return has_sequence ? openSequence(request) : openBags(request);
}

}  // namespace lvslam
