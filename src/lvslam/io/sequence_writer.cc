#include "lvslam/io/sequence_writer.h"

#include <filesystem>

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>

#include "lvslam/core/error.h"
#include "lvslam/core/timestamp.h"
#include "lvslam/io/scan_file.h"
#include "lvslam/io/tum.h"

namespace lvslam {

namespace fs = std::filesystem;

namespace {

std::ofstream openTimes(const fs::path& folder) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) throw Error(folder.string(), "cannot create folder: " + ec.message());
  std::ofstream out(folder / "times.txt");
  if (!out) throw Error((folder / "times.txt").string(), "cannot write file");
  out << "# timestamp file\n";
  return out;
}

}  // namespace

SequenceWriter::SequenceWriter(const std::string& directory, const SequenceInfo& info)
    : directory_(directory), info_(info) {
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec) throw Error(directory, "cannot create folder: " + ec.message());
  writeSequenceInfo((fs::path(directory) / "sequence.yaml").string(), info_);
  if (info_.camera) camera_times_ = openTimes(fs::path(directory) / "camera");
  if (info_.lidar) lidar_times_ = openTimes(fs::path(directory) / "lidar");
}

void SequenceWriter::writeImage(double t, const cv::Mat& image) {
  if (!info_.camera) throw Error(directory_, "the sequence has no camera");
  if (camera_count_ > 0 && !(t > last_camera_t_))
    throw Error(directory_, fmt::format("camera time stamp {} does not increase", formatTimestamp(t)));
  if (image.depth() != CV_8U || (image.channels() != 1 && image.channels() != 3))
    throw Error(directory_, "images must be 8-bit grayscale or BGR");
  const std::string name = fmt::format("{:06d}.png", camera_count_);
  const std::string path = (fs::path(directory_) / "camera" / name).string();
  if (!cv::imwrite(path, image)) throw Error(path, "cannot write image");
  camera_times_ << formatTimestamp(t) << " " << name << "\n";
  if (!camera_times_) throw Error(directory_ + "/camera/times.txt", "write failed");
  last_camera_t_ = t;
  ++camera_count_;
}

void SequenceWriter::writeScan(const LidarScan& scan) {
  if (!info_.lidar) throw Error(directory_, "the sequence has no lidar");
  if (lidar_count_ > 0 && !(scan.timestamp > last_lidar_t_))
    throw Error(directory_, fmt::format("lidar time stamp {} does not increase", formatTimestamp(scan.timestamp)));
  const std::string name = fmt::format("{:06d}.bin", lidar_count_);
  writeScanFile((fs::path(directory_) / "lidar" / name).string(), info_.lidar->point_fields, scan);
  lidar_times_ << formatTimestamp(scan.timestamp) << " " << name << "\n";
  if (!lidar_times_) throw Error(directory_ + "/lidar/times.txt", "write failed");
  last_lidar_t_ = scan.timestamp;
  ++lidar_count_;
}

void SequenceWriter::writeGroundTruth(const Trajectory& trajectory) {
  if (!info_.groundtruth_frame)
    throw Error(directory_, "groundtruth.frame must be set in the sequence info to write ground truth");
  writeTum((fs::path(directory_) / "groundtruth.txt").string(), trajectory);
}

}  // namespace lvslam
