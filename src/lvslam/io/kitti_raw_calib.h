#pragma once
// KITTI raw calibration (calib_cam_to_cam.txt, calib_velo_to_cam.txt,
// calib_imu_to_velo.txt of a date folder such as 2011_09_26/).
#include <string>

#include <Eigen/Geometry>

#include "lvslam/core/camera.h"

namespace lvslam {

struct KittiRawCalibration {
  int camera_index = 0;             // 0 (left gray) or 2 (left colour)
  PinholeCamera camera;             // of the rectified image: P_rect_0X's fx, fy, cx, cy; S_rect_0X's size
  Eigen::Matrix<double, 3, 4> P_rect = Eigen::Matrix<double, 3, 4>::Zero();  // P_rect_0X as given
  Eigen::Matrix3d R_rect_00 = Eigen::Matrix3d::Identity();
  Eigen::Isometry3d T_cam0_velo = Eigen::Isometry3d::Identity();  // Tr_velo_to_cam (unrectified camera 0)
  Eigen::Isometry3d T_velo_imu = Eigen::Isometry3d::Identity();   // Tr_imu_to_velo
  // p_camera = T_camera_lidar * p_velo with [fx 0 cx; 0 fy cy; 0 0 1] * p_camera
  // equal to P_rect_0X * R_rect_00 * Tr_velo_to_cam * p_velo (KITTI raw devkit):
  // T_camera_lidar = [I | K^-1 P_rect(:,3)] * R_rect_00 * Tr_velo_to_cam. The
  // rotation part is KITTI's product as given (orthonormal to ~1e-6 only).
  Eigen::Isometry3d T_camera_lidar = Eigen::Isometry3d::Identity();
};

// Reads the three files of calib_dir. Throws lvslam::Error naming the file
// and key on a missing file, key or malformed number.
KittiRawCalibration readKittiRawCalibration(const std::string& calib_dir, int camera_index);

}  // namespace lvslam
