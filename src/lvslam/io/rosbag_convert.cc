#include "lvslam/io/rosbag_convert.h"

#include <filesystem>

#include <fmt/format.h>

#include "lvslam/core/error.h"
#include "lvslam/io/atomic_folder.h"
#include "lvslam/io/rosbag_source.h"
#include "lvslam/io/sequence_writer.h"
#include "lvslam/io/tum.h"

namespace lvslam {

namespace {

BagSourceOptions sourceOptions(const BagConvertOptions& options) {
  BagSourceOptions s;
  s.lidar_topic = options.lidar_topic;
  s.camera_topic = options.camera_topic;
  if (options.preset) {
    if (s.lidar_topic.empty()) s.lidar_topic = options.preset->lidar_topic;
    if (s.camera_topic.empty()) s.camera_topic = options.preset->camera_topic;
    s.calibration = options.preset->calibration();
    s.lidar = options.preset->lidar;
  }
  if (!s.camera_topic.empty() && !s.calibration.camera)
    throw Error(s.camera_topic, "a camera topic needs the camera's intrinsics: give a preset with a 'camera' block");
  return s;
}

std::optional<GroundTruthFrame> groundTruthFrame(const BagConvertOptions& options) {
  if (options.groundtruth_path.empty()) return std::nullopt;
  if (options.groundtruth_frame) return options.groundtruth_frame;
  if (options.preset && options.preset->groundtruth_frame) return options.preset->groundtruth_frame;
  throw Error(options.groundtruth_path, "the frame of the ground truth is unknown: give it (camera or lidar) "
                                        "or a preset with 'groundtruth.frame'");
}

void checkImageSize(const cv::Mat& image, const PinholeCamera& camera, const std::string& topic, double t) {
  if (image.cols != camera.width() || image.rows != camera.height())
    throw Error(fmt::format("topic {}", topic),
                fmt::format("image at {:.6f} is {} x {}, the preset's camera is {} x {}", t, image.cols, image.rows,
                            camera.width(), camera.height()));
}

}  // namespace

BagConvertStats convertBags(const BagConvertOptions& options) {
  const BagSourceOptions source_options = sourceOptions(options);
  BagSource source(options.bags, source_options);
  // Validated before anything is written.
  const std::optional<GroundTruthFrame> gt_frame = groundTruthFrame(options);
  const Trajectory groundtruth = options.groundtruth_path.empty() ? Trajectory{} : readTum(options.groundtruth_path);

  SequenceInfo info;
  info.name = options.name.empty() ? std::filesystem::path(options.out_dir).filename().string() : options.name;
  if (source.hasCamera()) info.camera = CameraInfo{*source_options.calibration.camera,
                                                   options.preset && options.preset->camera ? options.preset->camera->rate_hz : 0.0};
  if (source.hasLidar()) info.lidar = source.lidarInfo();
  info.T_camera_lidar = source_options.calibration.T_camera_lidar;
  info.groundtruth_frame = gt_frame;

  BagConvertStats stats;
  stats.lidar = source.lidarInfo();
  writeFolderAtomically(options.out_dir, [&](const std::string& dir) {
    SequenceWriter writer(dir, info);
    while (auto data = source.next()) {
      if (const auto* image = std::get_if<ImageFrame>(&*data)) {
        checkImageSize(image->image, info.camera->camera, source_options.camera_topic, image->timestamp);
        writer.writeImage(image->timestamp, image->image);
        ++stats.images;
      } else {
        const auto& scan = std::get<LidarScan>(*data);
        writer.writeScan(scan);
        ++stats.scans;
        stats.points += scan.size();
      }
    }
    if (gt_frame) {
      writer.writeGroundTruth(groundtruth);
      stats.groundtruth = groundtruth.size();
    }
  });
  stats.skipped = source.skippedMessages();
  return stats;
}

}  // namespace lvslam
