#include "lvslam/io/kitti_raw_convert.h"

#include <filesystem>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "lvslam/core/error.h"
#include "lvslam/io/atomic_folder.h"
#include "lvslam/io/image_file.h"
#include "lvslam/io/kitti_raw_calib.h"
#include "lvslam/io/kitti_raw_oxts.h"
#include "lvslam/io/kitti_raw_time.h"
#include "lvslam/io/scan_file.h"
#include "lvslam/io/sequence_writer.h"

namespace lvslam {

namespace fs = std::filesystem;

namespace {

constexpr double kCameraRateHz = 10.0;  // KITTI raw: cameras triggered by the Velodyne at 10 Hz
const std::vector<std::string> kVelodyneFields{"x", "y", "z", "intensity"};

bool warnIfNotIncreasing(const std::string& what, std::size_t index, double t, double last, std::size_t count) {
  if (count == 0 || t > last) return false;
  spdlog::warn("{}: frame {} time stamp {:.9f} does not increase (previous {:.9f}); skipped", what, index, t, last);
  return true;
}

// Scan time stamps: the sweep start when the drive has it (velodyne
// timestamps.txt is when the laser faced forward, mid-sweep).
std::vector<double> scanTimes(const fs::path& velodyne) {
  const fs::path start = velodyne / "timestamps_start.txt";
  if (fs::exists(start)) return readKittiTimestamps(start.string());
  spdlog::warn("{}: no timestamps_start.txt; scans stamped with timestamps.txt (mid-sweep)", velodyne.string());
  return readKittiTimestamps((velodyne / "timestamps.txt").string());
}

void writeImages(const fs::path& image_dir, SequenceWriter& writer, KittiRawConvertStats& stats) {
  const std::vector<double> times = readKittiTimestamps((image_dir / "timestamps.txt").string());
  double last = 0.0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    const std::string path = (image_dir / "data" / fmt::format("{:010d}.png", i)).string();
    if (warnIfNotIncreasing(image_dir.string(), i, times[i], last, stats.images)) {
      ++stats.skipped;
      continue;
    }
    const cv::Mat image = readImageFile(path);
    writer.writeImage(times[i], image);
    last = times[i];
    ++stats.images;
  }
}

void writeScans(const fs::path& velodyne, SequenceWriter& writer, KittiRawConvertStats& stats) {
  const std::vector<double> times = scanTimes(velodyne);
  const ScanLayout layout = ScanLayout::fromFields(kVelodyneFields);
  double last = 0.0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (warnIfNotIncreasing(velodyne.string(), i, times[i], last, stats.scans)) {
      ++stats.skipped;
      continue;
    }
    LidarScan scan;
    readScanFile((velodyne / "data" / fmt::format("{:010d}.bin", i)).string(), layout, scan);
    scan.timestamp = times[i];
    writer.writeScan(scan);
    last = times[i];
    ++stats.scans;
  }
}

Trajectory groundTruth(const KittiRawConvertOptions& options, const KittiRawCalibration& calib) {
  const Trajectory imu = readOxtsTrajectory((fs::path(options.drive_dir) / "oxts").string());
  // T_world_lidar = T_world_imu * T_imu_velo; the camera further by T_lidar_camera.
  const Eigen::Isometry3d T_imu_sensor =
      options.groundtruth_frame == GroundTruthFrame::kLidar ? calib.T_velo_imu.inverse()
                                                            : calib.T_velo_imu.inverse() * calib.T_camera_lidar.inverse();
  Trajectory out;
  for (const StampedPose& p : imu) {
    if (!out.empty() && !(p.t > out.back().t)) continue;  // SequenceWriter needs increasing stamps
    out.push_back({p.t, p.T_world_frame * T_imu_sensor});
  }
  return out;
}

}  // namespace

KittiRawConvertStats convertKittiRaw(const KittiRawConvertOptions& options) {
  const KittiRawCalibration calib = readKittiRawCalibration(options.calib_dir, options.camera);
  const fs::path drive(options.drive_dir);
  const fs::path image_dir = drive / fmt::format("image_{:02d}", options.camera);
  const fs::path velodyne = drive / "velodyne_points";
  if (!fs::is_directory(image_dir)) throw Error(image_dir.string(), "no such folder");
  if (!fs::is_directory(velodyne)) throw Error(velodyne.string(), "no such folder");
  const bool has_oxts = fs::is_directory(drive / "oxts");
  const Trajectory gt = has_oxts ? groundTruth(options, calib) : Trajectory{};

  SequenceInfo info;
  info.name = options.name.empty() ? fs::path(options.drive_dir).lexically_normal().filename().string() : options.name;
  if (info.name.empty()) info.name = fs::path(options.drive_dir).parent_path().filename().string();
  info.camera = CameraInfo{calib.camera, kCameraRateHz};
  LidarInfo lidar;
  lidar.rings = 64;  // Velodyne HDL-64E
  lidar.rate_hz = 10.0;
  lidar.point_fields = kVelodyneFields;
  lidar.time_reference = TimeReference::kStart;  // the points carry no time; see scanTimes
  info.lidar = lidar;
  info.T_camera_lidar = calib.T_camera_lidar;
  if (has_oxts) info.groundtruth_frame = options.groundtruth_frame;

  KittiRawConvertStats stats;
  writeFolderAtomically(options.out_dir, [&](const std::string& dir) {
    SequenceWriter writer(dir, info);
    writeImages(image_dir, writer, stats);
    writeScans(velodyne, writer, stats);
    if (has_oxts) writer.writeGroundTruth(gt);
  });
  if (has_oxts) {
    stats.groundtruth = gt.size();
  } else {
    spdlog::warn("{}: no oxts/ folder, the sequence has no ground truth", options.drive_dir);
  }
  return stats;
}

}  // namespace lvslam
