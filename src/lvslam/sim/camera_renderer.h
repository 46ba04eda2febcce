#pragma once
// Renders what the scenario's camera sees: exact ray casting per pixel (with
// the lens distortion when set), primitives culled per 16 x 16 tile by their
// projected bounding polytope, Lambertian light, sub-exposures averaged for
// motion blur, rolling shutter (each row from the pose at its own time),
// vignetting, lens softness and sensor noise. Glass panes are seen through.
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "lvslam/sim/scenario.h"

namespace lvslam::sim {

class CameraRenderer {
 public:
  // The scenario must outlive the renderer.
  explicit CameraRenderer(const Scenario& scenario);

  // 8-bit grayscale image exposed at t (seconds after the sequence start)
  // with the scenario's base exposure, or with `exposure` (auto-exposure).
  // Its noise is keyed by (seed, t): the same call gives the same bytes.
  cv::Mat renderImage(double t) const;
  cv::Mat renderImage(double t, const Exposure& exposure) const;
  // When row y is exposed (the middle of its exposure) for an image stamped t.
  double rowTime(double t, int y) const;
  // Depth z (metres along the optical axis) per pixel at t, 0 where the ray
  // meets nothing (sky). CV_32F, no blur, no noise.
  cv::Mat renderDepth(double t) const;

 private:
  struct Tile {
    int x0, y0, x1, y1;                  // pixel range [x0, x1) x [y0, y1)
    Eigen::Vector2d lo, hi;              // bounds of its rays' normalised coordinates
  };
  // Per tile of rows [y0, y1), the indices of `primitives` whose projection,
  // widened by `margin` (normalised coordinates), may cover it; glass is
  // never listed.
  void cullPerTile(const std::vector<Primitive>& primitives, const Eigen::Isometry3d& T_world_camera, int y0,
                   int y1, double margin, std::vector<std::vector<int>>& lists) const;
  // Radiance (and depth, when asked) of every pixel at one instant.
  void renderInstant(double t, cv::Mat& radiance, cv::Mat* depth) const;
  double radianceOf(const Eigen::Vector3d& point, const Eigen::Vector3d& normal, double albedo) const;

  const Scenario& scenario_;
  std::vector<Eigen::Vector3d> rays_;  // per pixel, camera frame, unit length
  std::vector<Tile> tiles_;            // row by row of tiles
  int tile_columns_ = 0;
  // Bounds of the normalised coordinates over each column and each row of
  // tiles: a primitive is tested only against the tiles in the columns and
  // rows its bounds overlap.
  std::vector<Eigen::Vector2d> column_x_, row_y_;
  cv::Mat vignette_;                   // CV_32F gain per pixel
  double pixel_angle_ = 0.0;
};

}  // namespace lvslam::sim
