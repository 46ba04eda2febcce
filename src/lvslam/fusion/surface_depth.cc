#include "lvslam/fusion/surface_depth.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lvslam/visual/match/feature_grid.h"

namespace lvslam::fusion {

std::vector<double> surfaceDepths(const std::vector<visual::PixelDepth>& samples,
                                  const std::vector<Eigen::Vector2d>& pixels, double radius_px, int width,
                                  int height) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> depths(pixels.size(), kNaN);
  if (!(radius_px > 0.0) || !std::isfinite(radius_px)) return depths;
  std::vector<Eigen::Vector2d> sample_pixels;
  std::vector<double> sample_depths;
  for (const visual::PixelDepth& s : samples) {
    if (!s.pixel.allFinite() || !std::isfinite(s.depth) || !(s.depth > 0.0)) continue;
    sample_pixels.push_back(s.pixel);
    sample_depths.push_back(s.depth);
  }
  if (sample_pixels.empty()) return depths;
  // Cells of the radius (at most the image): a pixel's neighbours lie in the cells around it.
  const double cell = std::ceil(std::min(radius_px, static_cast<double>(std::max({width, height, 1}))));
  const visual::FeatureGrid grid(sample_pixels, width, height, static_cast<int>(cell));
  std::vector<int> near_ids;
  std::vector<double> near;
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    grid.query(pixels[i], radius_px, near_ids);  // nothing for a non-finite pixel
    if (near_ids.size() < 2) continue;
    near.clear();
    for (const int j : near_ids) near.push_back(sample_depths[j]);
    // The nearest surface wins (points behind it show through by parallax);
    // it needs a second point within 5 % to count as a surface, not a stray.
    std::sort(near.begin(), near.end());
    double sum = 0.0;
    int count = 0;
    for (const double z : near)
      if (z <= near.front() * 1.05) sum += z, ++count;
    if (count >= 2) depths[i] = sum / count;
  }
  return depths;
}

}  // namespace lvslam::fusion
