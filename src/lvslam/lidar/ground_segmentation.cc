#include "lvslam/lidar/ground_segmentation.h"

#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>
#include <tsl/robin_map.h>

#include "lvslam/lidar/voxel_key.h"

namespace lvslam::lidar {

namespace {

struct Cell {
  float min_z = std::numeric_limits<float>::max();
  std::vector<int> members;
};

using CellKey = Eigen::Vector3i;  // (x, y, 0): voxelOf with z flattened

// Upward unit normal of the best plane through the points, and its mean.
bool fitPlane(const std::vector<TimedPoint>& points, const std::vector<int>& ids, Eigen::Vector3d& normal,
              Eigen::Vector3d& centroid) {
  centroid.setZero();
  for (int i : ids) centroid += points[i].p.cast<double>();
  centroid /= static_cast<double>(ids.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (int i : ids) {
    const Eigen::Vector3d d = points[i].p.cast<double>() - centroid;
    cov += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(cov);
  normal = solver.eigenvectors().col(0);
  if (normal.z() < 0) normal = -normal;
  return normal.allFinite();
}

}  // namespace

GroundSegmentation segmentGround(const std::vector<TimedPoint>& points, const GroundConfig& config) {
  GroundSegmentation result{std::vector<bool>(points.size(), false),
                            std::vector<Eigen::Vector3f>(points.size(), Eigen::Vector3f::UnitZ())};
  tsl::robin_map<CellKey, Cell, VoxelKeyHash> cells;
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    const Eigen::Vector3f& p = points[i].p;
    if (p.z() > config.max_sensor_height) continue;
    CellKey key = voxelOf(p, config.grid_size);
    key.z() = 0;
    Cell& cell = cells[key];
    cell.min_z = std::min(cell.min_z, p.z());
    cell.members.push_back(i);
  }
  const double cos_max = std::cos(config.max_normal_angle_deg * M_PI / 180.0);
  std::vector<int> candidates;
  for (const auto& [key, cell] : cells) {
    candidates.clear();
    for (int i : cell.members)
      if (points[i].p.z() < cell.min_z + config.height_threshold) candidates.push_back(i);
    if (static_cast<int>(candidates.size()) < config.min_points_per_cell) continue;
    Eigen::Vector3d normal, centroid;
    if (!fitPlane(points, candidates, normal, centroid) || normal.z() < cos_max) continue;
    // Refit on the inliers: the feet of walls and boxes lie within the height
    // threshold of the floor but not on it.
    std::erase_if(candidates, [&](int i) {
      return std::abs(normal.dot(points[i].p.cast<double>() - centroid)) > config.inlier_distance;
    });
    if (static_cast<int>(candidates.size()) < config.min_points_per_cell) continue;
    if (!fitPlane(points, candidates, normal, centroid) || normal.z() < cos_max) continue;
    for (int i : candidates) {
      if (std::abs(normal.dot(points[i].p.cast<double>() - centroid)) > config.inlier_distance) continue;
      result.is_ground[i] = true;
      result.normal[i] = normal.cast<float>();
    }
  }
  return result;
}

}  // namespace lvslam::lidar
