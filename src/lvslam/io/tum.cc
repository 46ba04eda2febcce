#include "lvslam/io/tum.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <fstream>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "lvslam/core/error.h"
#include "lvslam/core/file_access.h"
#include "lvslam/core/se3.h"
#include "lvslam/core/timestamp.h"

namespace lvslam {

namespace {

std::string at(const std::string& path, int line) { return path + ":" + std::to_string(line); }

bool isSkippable(const std::string& line) {
  const auto first = line.find_first_not_of(" \t\r");
  return first == std::string::npos || line[first] == '#';
}

// Splits a line into finite numbers; false if any token is not one.
bool parseNumbers(const std::string& line, std::vector<double>& values) {
  values.clear();
  std::istringstream ss(line);
  std::string token;
  while (ss >> token) {
    double v = 0.0;
    if (!parseTimestamp(token, v)) return false;
    values.push_back(v);
  }
  return true;
}

std::ifstream openOrThrow(const std::string& path) { return openInputFile(path); }

void checkIncreasing(const std::string& path, int line_no, const Trajectory& traj, double t) {
  if (!traj.empty() && !(t > traj.back().t))
    throw Error(at(path, line_no), fmt::format("time stamp {} does not increase (previous {})",
                                               formatTimestamp(t), formatTimestamp(traj.back().t)));
}

std::string tumLine(const StampedPose& sp) {
  Eigen::Quaterniond q(sp.T_world_frame.linear());
  q.normalize();
  const Eigen::Vector3d t = sp.T_world_frame.translation();
  return fmt::format("{} {:.9f} {:.9f} {:.9f} {:.9f} {:.9f} {:.9f} {:.9f}\n", formatTimestamp(sp.t), t.x(), t.y(),
                     t.z(), q.x(), q.y(), q.z(), q.w());
}

}  // namespace

Trajectory readTum(const std::string& path) {
  std::ifstream in = openOrThrow(path);
  Trajectory traj;
  // Sized once: a long ground truth (hundreds of thousands of poses) would
  // otherwise hold half again its size while the vector grows.
  traj.reserve(static_cast<std::size_t>(std::count(std::istreambuf_iterator<char>(in), {}, '\n')) + 1);
  in.clear();
  in.seekg(0);
  std::string line;
  std::vector<double> v;
  for (int line_no = 1; std::getline(in, line); ++line_no) {
    if (isSkippable(line)) continue;
    if (!parseNumbers(line, v) || v.size() != 8)
      throw Error(at(path, line_no), "expected 8 numbers 'timestamp tx ty tz qx qy qz qw'");
    const Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);
    if (!(q.norm() > 1e-6))
      throw Error(at(path, line_no), "quaternion has zero norm (orientation missing)");
    checkIncreasing(path, line_no, traj, v[0]);
    traj.push_back({v[0], makePose(q, Eigen::Vector3d(v[1], v[2], v[3]))});
  }
  return traj;
}

void writeTum(const std::string& path, const Trajectory& trajectory) {
  std::ofstream out(path);
  if (!out) throw Error(path, "cannot write file");
  for (const auto& sp : trajectory) out << tumLine(sp);
  if (!out) throw Error(path, "write failed");
}

TumStream::TumStream(const std::string& path) : path_(path), out_(path) {
  if (!out_) throw Error(path, "cannot write file");
}

void TumStream::add(const StampedPose& pose) {
  out_ << tumLine(pose) << std::flush;
  if (!out_) throw Error(path_, "write failed");
}

Trajectory readKittiPoses(const std::string& path, const std::string& times_path) {
  std::vector<double> times;
  if (!times_path.empty()) {
    std::ifstream tin = openOrThrow(times_path);
    std::string line;
    std::vector<double> v;
    for (int line_no = 1; std::getline(tin, line); ++line_no) {
      if (isSkippable(line)) continue;
      if (!parseNumbers(line, v) || v.size() != 1)
        throw Error(at(times_path, line_no), "expected one time stamp");
      if (!times.empty() && !(v[0] > times.back()))
        throw Error(at(times_path, line_no), "time stamps must increase");
      times.push_back(v[0]);
    }
  }
  std::ifstream in = openOrThrow(path);
  Trajectory traj;
  std::string line;
  std::vector<double> v;
  int pose_index = 0;
  for (int line_no = 1; std::getline(in, line); ++line_no) {
    if (isSkippable(line)) continue;
    if (!parseNumbers(line, v) || v.size() != 12)
      throw Error(at(path, line_no), "expected 12 numbers (row-major 3x4 [R|t])");
    Eigen::Matrix3d R;
    R << v[0], v[1], v[2], v[4], v[5], v[6], v[8], v[9], v[10];
    if (!isRotation(R)) throw Error(at(path, line_no), "rotation part is not a rotation");
    double t = pose_index;
    if (!times_path.empty()) {
      if (pose_index >= static_cast<int>(times.size()))
        throw Error(times_path, fmt::format("fewer time stamps ({}) than poses in {}", times.size(), path));
      t = times[pose_index];
    }
    // Kept as written (no re-orthonormalisation), as evo reads them.
    traj.push_back({t, makePose(R, Eigen::Vector3d(v[3], v[7], v[11]))});
    ++pose_index;
  }
  if (!times_path.empty() && times.size() != traj.size())
    throw Error(times_path, fmt::format("{} time stamps for {} poses in {}", times.size(), traj.size(), path));
  return traj;
}

}  // namespace lvslam
