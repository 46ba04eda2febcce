#include "lvslam/visual/match/feature_grid.h"

#include <algorithm>
#include <cmath>

namespace lvslam::visual {

namespace {
// Cell index of a coordinate, clamped in floating point first so that huge
// values cannot overflow the int conversion.
int cellOf(double v, int cell, int count) {
  return static_cast<int>(std::clamp(std::floor(v / cell), 0.0, static_cast<double>(count - 1)));
}
}  // namespace

FeatureGrid::FeatureGrid(const std::vector<Eigen::Vector2d>& points, int width, int height, int cell_size)
    : points_(points), cols_(std::max(1, (width + cell_size - 1) / cell_size)),
      rows_(std::max(1, (height + cell_size - 1) / cell_size)), cell_(cell_size),
      cells_(static_cast<size_t>(cols_) * rows_) {
  for (size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite()) continue;
    const int cx = cellOf(points[i].x(), cell_, cols_);
    const int cy = cellOf(points[i].y(), cell_, rows_);
    cells_[static_cast<size_t>(cy) * cols_ + cx].push_back(static_cast<int>(i));
  }
}

void FeatureGrid::query(const Eigen::Vector2d& center, double radius, std::vector<int>& out) const {
  out.clear();
  if (!center.allFinite() || !(radius >= 0.0)) return;
  if (!std::isfinite(radius)) return;
  const int x0 = cellOf(center.x() - radius, cell_, cols_), x1 = cellOf(center.x() + radius, cell_, cols_);
  const int y0 = cellOf(center.y() - radius, cell_, rows_), y1 = cellOf(center.y() + radius, cell_, rows_);
  const double r2 = radius * radius;
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      for (const int i : cells_[static_cast<size_t>(y) * cols_ + x]) {
        if ((points_[i] - center).squaredNorm() <= r2) out.push_back(i);
      }
    }
  }
}

}  // namespace lvslam::visual
