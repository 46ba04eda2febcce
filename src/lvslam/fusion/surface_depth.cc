#include "lvslam/fusion/surface_depth.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace lvslam::fusion {

std::vector<double> surfaceDepths(const std::vector<visual::PixelDepth>& samples,
                                  const std::vector<Eigen::Vector2d>& pixels, double radius_px) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> depths(pixels.size(), kNaN);
  if (!(radius_px > 0.0)) return depths;
  // Bucket the samples in cells of radius_px: a pixel's neighbours are in the 3 x 3 cells around it.
  const double cell = radius_px;
  auto key = [cell](double u, double v) {
    const auto iu = static_cast<std::uint32_t>(static_cast<std::int32_t>(std::floor(u / cell)));
    const auto iv = static_cast<std::uint32_t>(static_cast<std::int32_t>(std::floor(v / cell)));
    return (static_cast<std::uint64_t>(iu) << 32) | iv;
  };
  std::unordered_map<std::uint64_t, std::vector<const visual::PixelDepth*>> grid;
  for (const visual::PixelDepth& s : samples)
    if (s.pixel.allFinite() && std::isfinite(s.depth) && s.depth > 0.0) grid[key(s.pixel.x(), s.pixel.y())].push_back(&s);
  std::vector<double> near;
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    if (!pixels[i].allFinite()) continue;
    near.clear();
    for (int du = -1; du <= 1; ++du)
      for (int dv = -1; dv <= 1; ++dv) {
        const auto it = grid.find(key(pixels[i].x() + du * cell, pixels[i].y() + dv * cell));
        if (it == grid.end()) continue;
        for (const visual::PixelDepth* s : it->second)
          if ((s->pixel - pixels[i]).norm() <= radius_px) near.push_back(s->depth);
      }
    if (near.size() < 2) continue;
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
