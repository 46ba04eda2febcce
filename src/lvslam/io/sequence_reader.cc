#include "lvslam/io/sequence_reader.h"

#include <filesystem>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "lvslam/core/error.h"
#include "lvslam/core/file_access.h"
#include "lvslam/io/atomic_folder.h"
#include "lvslam/io/clock_check.h"
#include "lvslam/io/image_file.h"
#include "lvslam/io/intrinsics_check.h"
#include "lvslam/io/point_field_check.h"
#include "lvslam/io/tum.h"

namespace lvslam {

namespace fs = std::filesystem;

namespace {

void warnAboutJumps(const std::vector<TimedFile>& files, const std::string& what) {
  // A gap is recoverable (the subsystems predict across it), so warn only.
  for (const std::size_t i : findTimeJumps(files))
    spdlog::warn("{}: time jumps by {:.3f} s before {} (a drop-out; the odometry predicts across it)", what,
                 files[i].t - files[i - 1].t, files[i].path);
}

// A declared sensor without data is read as absent (hasCamera/hasLidar), so
// the run picks the mode the other sensor feeds instead of giving no pose.
void warnIfEmpty(const std::vector<TimedFile>& files, const std::string& times, const std::string& what) {
  if (files.empty()) spdlog::warn("{}: lists no {}; the sequence is read without this sensor", times, what);
}

}  // namespace

SequenceReader::SequenceReader(const std::string& directory) : directory_(directory) {
  if (fileKind(directory) != FileKind::kDirectory) throw Error(directory, "sequence folder not found");
  info_ = readSequenceInfo((fs::path(directory) / "sequence.yaml").string());
  const std::string marker = (fs::path(directory) / kIncompleteMarker).string();
  if (fileKind(marker) != FileKind::kMissing)
    throw Error(marker, "the folder is incomplete: the conversion that wrote it did not finish");
  const std::string camera_times = (fs::path(directory) / "camera" / "times.txt").string();
  const std::string lidar_times = (fs::path(directory) / "lidar" / "times.txt").string();
  if (info_.camera) {
    camera_files_ = readTimesFile(camera_times);
    plausibility_warnings_ = intrinsicsWarnings(info_.camera->camera, (fs::path(directory) / "sequence.yaml").string());
  }
  if (info_.lidar) {
    lidar_files_ = readTimesFile(lidar_times);
    layout_ = ScanLayout::fromFields(info_.lidar->point_fields);
    for (std::string& warning :
         pointFieldWarnings(info_.lidar->point_fields, (fs::path(directory) / "sequence.yaml").string()))
      plausibility_warnings_.push_back(std::move(warning));
  }
  // A clock jump is an error; only then are the remaining gaps drop-outs.
  checkClocksAgree(camera_files_, camera_times, lidar_files_, lidar_times);
  if (info_.camera) {
    warnAboutJumps(camera_files_, camera_times);
    warnIfEmpty(camera_files_, camera_times, "image");
  }
  if (info_.lidar) {
    warnAboutJumps(lidar_files_, lidar_times);
    warnIfEmpty(lidar_files_, lidar_times, "scan");
  }
  if (hasGroundTruth() && !info_.groundtruth_frame)
    throw Error((fs::path(directory) / "sequence.yaml").string(),
                "key 'groundtruth.frame': missing required key (groundtruth.txt exists)");
}

Calibration SequenceReader::calibration() const {
  Calibration c = info_.calibration();
  c.T_camera_lidar_source = (fs::path(directory_) / "sequence.yaml").string() + ": key 'extrinsics.T_camera_lidar'";
  return c;
}

bool SequenceReader::hasGroundTruth() const {
  return fileKind((fs::path(directory_) / "groundtruth.txt").string()) == FileKind::kRegular;
}

Trajectory SequenceReader::groundTruth() const {
  return readTum((fs::path(directory_) / "groundtruth.txt").string());
}

std::optional<SensorData> SequenceReader::next() {
  const bool camera_left = next_camera_ < camera_files_.size();
  const bool lidar_left = next_lidar_ < lidar_files_.size();
  if (!camera_left && !lidar_left) return std::nullopt;
  SensorData data = lidar_left && (!camera_left || lidar_files_[next_lidar_].t <= camera_files_[next_camera_].t)
                        ? SensorData(loadScan(next_lidar_++))
                        : SensorData(loadImage(next_camera_++));
  // After the first file read, so that a bad first file is one error line.
  for (const std::string& warning : plausibility_warnings_) spdlog::warn("{}", warning);
  plausibility_warnings_.clear();
  return data;
}

ImageFrame SequenceReader::loadImage(std::size_t index) const {
  const TimedFile& f = camera_files_.at(index);
  ImageFrame frame;
  frame.timestamp = f.t;
  frame.image = readImageFile(f.path);
  if (frame.image.depth() != CV_8U) throw Error(f.path, "image is not 8-bit");
  const int channels = frame.image.channels();
  if (channels != 1 && channels != 3)
    throw Error(f.path, fmt::format("image has {} channels; expected grayscale or BGR", channels));
  const PinholeCamera& cam = info_.camera->camera;
  if (frame.image.cols != cam.width() || frame.image.rows != cam.height())
    throw Error(f.path, fmt::format("image is {}x{} but sequence.yaml says camera {}x{}", frame.image.cols,
                                    frame.image.rows, cam.width(), cam.height()));
  return frame;
}

LidarScan SequenceReader::loadScan(std::size_t index) const {
  const TimedFile& f = lidar_files_.at(index);
  LidarScan scan;
  scan.timestamp = f.t;
  // An empty file is read as a scan without points (a documented recovery:
  // the odometry predicts across it), but not silently.
  if (readScanFile(f.path, *layout_, scan).records == 0)
    spdlog::warn("{}: empty scan file (no points); the odometry counts it lost and predicts across it", f.path);
  return scan;
}

}  // namespace lvslam
