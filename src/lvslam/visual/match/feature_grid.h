#pragma once
// Keypoints bucketed in a coarse image grid for radius queries (ORB-SLAM's
// frame grid): matching by projection looks only at nearby cells.
#include <vector>

#include <Eigen/Core>

namespace lvslam::visual {

class FeatureGrid {
 public:
  FeatureGrid() = default;
  // points: undistorted pixels; points outside [0, width) x [0, height) are
  // clamped into the border cells.
  FeatureGrid(const std::vector<Eigen::Vector2d>& points, int width, int height, int cell_size = 32);

  // Indices of points within radius of (x, y), appended to `out` (cleared first).
  void query(const Eigen::Vector2d& center, double radius, std::vector<int>& out) const;

 private:
  std::vector<Eigen::Vector2d> points_;  // a copy: the grid stays valid when the frame moves
  int cols_ = 0, rows_ = 0, cell_ = 32;
  std::vector<std::vector<int>> cells_;
};

}  // namespace lvslam::visual
