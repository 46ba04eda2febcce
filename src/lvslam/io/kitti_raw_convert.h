#pragma once
// `lvslam convert kitti-raw`: a KITTI raw synced drive (e.g.
// 2011_09_26/2011_09_26_drive_0001_sync/) to a sequence folder: the rectified
// images of camera 0 or 2, the Velodyne scans, the calibration chain, and the
// OXTS poses as ground truth.
#include <string>

#include "lvslam/io/sequence_info.h"

namespace lvslam {

struct KittiRawConvertOptions {
  std::string drive_dir;   // has image_0X/, velodyne_points/, oxts/
  std::string calib_dir;   // has calib_cam_to_cam.txt, calib_velo_to_cam.txt, calib_imu_to_velo.txt
  int camera = 0;          // 0: left gray, 2: left colour
  GroundTruthFrame groundtruth_frame = GroundTruthFrame::kLidar;
  std::string out_dir;
  std::string name;        // default: the drive folder's name
};

struct KittiRawConvertStats {
  std::size_t images = 0, scans = 0, groundtruth = 0;
  std::size_t skipped = 0;  // frames whose time stamp did not increase
};

// Throws lvslam::Error naming the file on missing or malformed input.
KittiRawConvertStats convertKittiRaw(const KittiRawConvertOptions& options);

}  // namespace lvslam
