#pragma once
// The depth of the nearest surface under image pixels, from LiDAR samples
// projected into the image (accumulated features in fused mode, raw points
// near the image time in visual mode).
#include <vector>

#include <Eigen/Core>

#include "lvslam/visual/tracking/map_initialization.h"

namespace lvslam::fusion {

// Per pixel the mean depth of the samples within radius_px that lie within
// 5 % of the nearest one; NaN where fewer than two such samples exist (and
// everywhere for a radius that is not positive and finite). width x height
// is the image the samples and pixels are in.
std::vector<double> surfaceDepths(const std::vector<visual::PixelDepth>& samples,
                                  const std::vector<Eigen::Vector2d>& pixels, double radius_px, int width,
                                  int height);

}  // namespace lvslam::fusion
