#pragma once
// The depth of the nearest surface under image pixels, from LiDAR samples
// projected into the image (accumulated features in fused mode, raw points
// near the image time in visual mode).
#include <vector>

#include <Eigen/Core>

namespace lvslam::visual {

// A depth sample: metric depth z in the camera frame at a pixel of the raw
// (distorted) image, e.g. a LiDAR point projected into it.
struct PixelDepth {
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
  double depth = 0.0;
};

// Per pixel the depth of the nearest surface among the samples within
// radius_px, read at the pixel through a local plane (inverse depth affine in
// the image point), so that a slanted surface, a wall or the floor at a
// grazing angle, is not read at its near edge: the farthest samples are
// dropped until the rest lie on one plane within 5 % of their depths. NaN
// where fewer than two samples remain (and everywhere for a radius that is
// not positive and finite). width x height is the image the samples and
// pixels are in.
std::vector<double> surfaceDepths(const std::vector<PixelDepth>& samples,
                                  const std::vector<Eigen::Vector2d>& pixels, double radius_px, int width,
                                  int height);

}  // namespace lvslam::visual
