#include "lvslam/visual/geometry/surface_depth.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "lvslam/visual/match/feature_grid.h"

namespace lvslam::visual {

namespace {

// A sample lies on the fitted surface when its depth is within this fraction
// of the surface's depth there; the nearest set that all do is the surface.
constexpr double kSurfaceTolerance = 0.05;
// A direction in the image along which the samples spread less than this
// (pixels, standard deviation) gives the surface no slope there.
constexpr double kMinSpreadPx = 1.0;

struct Sample {
  Eigen::Vector2d pixel;
  double depth;
};

// Inverse depth on a plane is an affine function of the image point (LIMO's
// local plane, Graeter et al., IROS 2018): fitted by least squares, with a
// slope only along directions the samples span and only with a sample more
// than the parameters (otherwise it could not be checked).
struct LocalPlane {
  Eigen::Vector2d mean_pixel = Eigen::Vector2d::Zero();
  double mean_inverse = 0.0;
  Eigen::Vector2d slope = Eigen::Vector2d::Zero();

  explicit LocalPlane(const std::vector<Sample>& samples, std::size_t count) {
    const double n = static_cast<double>(count);
    for (std::size_t i = 0; i < count; ++i) {
      mean_pixel += samples[i].pixel / n;
      mean_inverse += 1.0 / samples[i].depth / n;
    }
    Eigen::Matrix2d spread = Eigen::Matrix2d::Zero();
    Eigen::Vector2d cross = Eigen::Vector2d::Zero();
    for (std::size_t i = 0; i < count; ++i) {
      const Eigen::Vector2d d = samples[i].pixel - mean_pixel;
      spread += d * d.transpose();
      cross += d * (1.0 / samples[i].depth - mean_inverse);
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(spread);
    // Eigenvalues ascend: the wider direction first, then the other.
    std::size_t parameters = 1;
    for (int i = 1; i >= 0; --i) {
      if (eig.eigenvalues()(i) < n * kMinSpreadPx * kMinSpreadPx || count < parameters + 2) break;
      slope += eig.eigenvectors().col(i) * (eig.eigenvectors().col(i).dot(cross) / eig.eigenvalues()(i));
      ++parameters;
    }
  }
  double inverseAt(const Eigen::Vector2d& pixel) const { return mean_inverse + slope.dot(pixel - mean_pixel); }
  bool fits(const Sample& s) const {
    const double inverse = inverseAt(s.pixel);
    return inverse > 0.0 && std::abs(1.0 / inverse - s.depth) <= kSurfaceTolerance * s.depth;
  }
};

}  // namespace

std::vector<double> surfaceDepths(const std::vector<PixelDepth>& samples,
                                  const std::vector<Eigen::Vector2d>& pixels, double radius_px, int width,
                                  int height) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> depths(pixels.size(), kNaN);
  if (!(radius_px > 0.0) || !std::isfinite(radius_px)) return depths;
  std::vector<Eigen::Vector2d> sample_pixels;
  std::vector<double> sample_depths;
  for (const PixelDepth& s : samples) {
    if (!s.pixel.allFinite() || !std::isfinite(s.depth) || !(s.depth > 0.0)) continue;
    sample_pixels.push_back(s.pixel);
    sample_depths.push_back(s.depth);
  }
  if (sample_pixels.empty()) return depths;
  // Cells of the radius (at most the image): a pixel's neighbours lie in the cells around it.
  const double cell = std::ceil(std::min(radius_px, static_cast<double>(std::max({width, height, 1}))));
  const FeatureGrid grid(sample_pixels, width, height, static_cast<int>(cell));
  std::vector<int> near_ids;
  std::vector<Sample> near;
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    grid.query(pixels[i], radius_px, near_ids);  // nothing for a non-finite pixel
    if (near_ids.size() < 2) continue;
    near.clear();
    for (const int j : near_ids) near.push_back({sample_pixels[j], sample_depths[j]});
    // The nearest surface wins (points behind it show through by parallax):
    // the farthest samples go until the rest lie on one plane; it needs two
    // samples to count as a surface, not a stray.
    std::sort(near.begin(), near.end(), [](const Sample& a, const Sample& b) { return a.depth < b.depth; });
    for (std::size_t count = near.size(); count >= 2; --count) {
      const LocalPlane plane(near, count);
      if (!std::all_of(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(count),
                       [&](const Sample& s) { return plane.fits(s); }))
        continue;
      const double inverse = plane.inverseAt(pixels[i]);
      if (inverse > 0.0) depths[i] = 1.0 / inverse;
      break;
    }
  }
  return depths;
}

}  // namespace lvslam::visual
