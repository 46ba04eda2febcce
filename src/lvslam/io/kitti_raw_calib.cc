#include "lvslam/io/kitti_raw_calib.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "lvslam/core/error.h"
#include "lvslam/core/timestamp.h"

namespace lvslam {

namespace {

using CalibFile = std::map<std::string, std::vector<double>>;

// "key: n n n" lines; keys whose values are not numbers (calib_time) are kept empty.
CalibFile readCalibFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path, "cannot open calibration file");
  CalibFile file;
  std::string line;
  while (std::getline(in, line)) {
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::vector<double>& values = file[line.substr(0, colon)];
    std::istringstream ss(line.substr(colon + 1));
    std::string token;
    double v = 0.0;
    while (ss >> token && parseTimestamp(token, v)) values.push_back(v);
  }
  return file;
}

const std::vector<double>& need(const CalibFile& file, const std::string& path, const std::string& key,
                                std::size_t count) {
  const auto it = file.find(key);
  if (it == file.end()) throw Error(path, fmt::format("key '{}' missing", key));
  if (it->second.size() != count)
    throw Error(path, fmt::format("key '{}': expected {} numbers, got {}", key, count, it->second.size()));
  return it->second;
}

Eigen::Matrix3d rowMajor3(const std::vector<double>& v) {
  Eigen::Matrix3d M;
  for (int i = 0; i < 9; ++i) M(i / 3, i % 3) = v[i];
  return M;
}

// R (9) and T (3) of calib_velo_to_cam.txt / calib_imu_to_velo.txt, as given.
Eigen::Isometry3d readRigid(const std::string& path) {
  const CalibFile file = readCalibFile(path);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = rowMajor3(need(file, path, "R", 9));
  const std::vector<double>& t = need(file, path, "T", 3);
  T.translation() = Eigen::Vector3d(t[0], t[1], t[2]);
  return T;
}

}  // namespace

KittiRawCalibration readKittiRawCalibration(const std::string& calib_dir, int camera_index) {
  if (camera_index != 0 && camera_index != 2)
    throw Error("camera", fmt::format("expected 0 (gray) or 2 (colour), got {}", camera_index));
  namespace fs = std::filesystem;
  const std::string cam_path = (fs::path(calib_dir) / "calib_cam_to_cam.txt").string();
  const CalibFile cam = readCalibFile(cam_path);
  KittiRawCalibration c;
  c.camera_index = camera_index;
  const std::string suffix = fmt::format("_{:02d}", camera_index);
  const std::vector<double>& p = need(cam, cam_path, "P_rect" + suffix, 12);
  for (int i = 0; i < 12; ++i) c.P_rect(i / 4, i % 4) = p[i];
  c.R_rect_00 = rowMajor3(need(cam, cam_path, "R_rect_00", 9));
  const std::vector<double>& size = need(cam, cam_path, "S_rect" + suffix, 2);
  const Eigen::Matrix3d K = c.P_rect.leftCols<3>();
  if (!(K(0, 0) > 0.0) || !(K(1, 1) > 0.0) || K(2, 2) != 1.0 || K(2, 0) != 0.0 || K(2, 1) != 0.0)
    throw Error(cam_path, fmt::format("key 'P_rect{}': left 3x3 is not [fx 0 cx; 0 fy cy; 0 0 1]", suffix));
  c.camera = PinholeCamera(static_cast<int>(std::lround(size[0])), static_cast<int>(std::lround(size[1])), K(0, 0),
                           K(1, 1), K(0, 2), K(1, 2));

  c.T_cam0_velo = readRigid((fs::path(calib_dir) / "calib_velo_to_cam.txt").string());
  c.T_velo_imu = readRigid((fs::path(calib_dir) / "calib_imu_to_velo.txt").string());

  // P_rect_0X = K [I | t]: the 4th column is K t, t the offset of camera X from
  // rectified camera 0 (a baseline for camera 2).
  Eigen::Isometry3d T_camX_rect0 = Eigen::Isometry3d::Identity();
  T_camX_rect0.translation() = K.inverse() * c.P_rect.col(3);
  Eigen::Isometry3d T_rect0_cam0 = Eigen::Isometry3d::Identity();
  T_rect0_cam0.linear() = c.R_rect_00;
  c.T_camera_lidar = T_camX_rect0 * T_rect0_cam0 * c.T_cam0_velo;
  return c;
}

}  // namespace lvslam
