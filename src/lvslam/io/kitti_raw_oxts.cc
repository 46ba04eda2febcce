#include "lvslam/io/kitti_raw_oxts.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <fmt/format.h>

#include "lvslam/core/error.h"
#include "lvslam/io/kitti_raw_time.h"

namespace lvslam {

namespace {

constexpr double kEarthRadius = 6378137.0;  // the devkit's er, metres
constexpr double kDegree = std::numbers::pi / 180.0;

OxtsPacket readPacket(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path, "cannot open OXTS file");
  OxtsPacket p;
  // The first 6 of the 30 values: lat lon alt roll pitch yaw.
  if (!(in >> p.lat >> p.lon >> p.alt >> p.roll >> p.pitch >> p.yaw))
    throw Error(path, "expected lat lon alt roll pitch yaw as the first 6 numbers");
  for (double v : {p.lat, p.lon, p.alt, p.roll, p.pitch, p.yaw})
    if (!std::isfinite(v)) throw Error(path, "non-finite value among lat lon alt roll pitch yaw");
  return p;
}

}  // namespace

// KITTI raw devkit, convertOxtsToPose.m / latToScale.m / latlonToMercator.m.
std::vector<Eigen::Isometry3d> oxtsToPoses(const std::vector<OxtsPacket>& packets) {
  std::vector<Eigen::Isometry3d> poses;
  if (packets.empty()) return poses;
  const double scale = std::cos(packets.front().lat * kDegree);
  Eigen::Isometry3d T_first_inv = Eigen::Isometry3d::Identity();
  for (std::size_t i = 0; i < packets.size(); ++i) {
    const OxtsPacket& p = packets[i];
    const Eigen::Vector3d t(scale * p.lon * kDegree * kEarthRadius,
                            scale * kEarthRadius * std::log(std::tan((90.0 + p.lat) * std::numbers::pi / 360.0)), p.alt);
    const Eigen::Matrix3d R = (Eigen::AngleAxisd(p.yaw, Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(p.pitch, Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(p.roll, Eigen::Vector3d::UnitX())).toRotationMatrix();
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = R;
    T.translation() = t;
    if (i == 0) T_first_inv = T.inverse();
    poses.push_back(T_first_inv * T);
  }
  return poses;
}

Trajectory readOxtsTrajectory(const std::string& oxts_dir) {
  namespace fs = std::filesystem;
  const std::vector<double> times = readKittiTimestamps((fs::path(oxts_dir) / "timestamps.txt").string());
  std::vector<OxtsPacket> packets;
  for (std::size_t i = 0; i < times.size(); ++i)
    packets.push_back(readPacket((fs::path(oxts_dir) / "data" / fmt::format("{:010d}.txt", i)).string()));
  const std::vector<Eigen::Isometry3d> poses = oxtsToPoses(packets);
  Trajectory trajectory;
  for (std::size_t i = 0; i < times.size(); ++i) trajectory.push_back({times[i], poses[i]});
  return trajectory;
}

}  // namespace lvslam
