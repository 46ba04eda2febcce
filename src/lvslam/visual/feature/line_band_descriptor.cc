#include "lvslam/visual/feature/line_band_descriptor.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace lvslam::visual {

namespace {
// Band pairs whose statistics the bits compare: all 36 but the four farthest
// apart (their support barely overlaps the line), 32 pairs x 8 values = 256 bits.
constexpr std::array<std::pair<int, int>, 32> kBandPairs = [] {
  std::array<std::pair<int, int>, 32> pairs{};
  int n = 0;
  for (int i = 0; i < LineBandDescriptor::kBands; ++i) {
    for (int j = i + 1; j < LineBandDescriptor::kBands; ++j) {
      const bool farthest = (i == 0 && j >= 7) || (i == 1 && j >= 7);
      if (!farthest) pairs[n++] = {i, j};
    }
  }
  return pairs;
}();

int nearestClamped(float v, int size) {
  return std::clamp(static_cast<int>(std::max(v, 0.0f) + 0.5f), 0, size - 1);
}
}  // namespace

LineBandDescriptor::LineBandDescriptor() {
  // Zhang & Koch 2013, Sec. 3.1: f_g with sigma_g = (m w - 1) / 2 over the
  // region's rows, f_l with sigma_l = w around each band's centre row.
  const double centre = 0.5 * (kRows - 1);
  const double sigma_g = 0.5 * (kRows - 1), sigma_l = kBandWidth;
  for (int k = 0; k < kRows; ++k) {
    const double d = k - centre;
    global_weight_[k] = static_cast<float>(std::exp(-d * d / (2.0 * sigma_g * sigma_g)));
  }
  for (int j = 0; j < kBands; ++j) {
    const double band_centre = j * kBandWidth + 0.5 * (kBandWidth - 1);
    for (int k = 0; k < kRows; ++k) {
      const int band = k / kBandWidth;
      const double d = k - band_centre;
      band_weight_[j][k] =
          std::abs(band - j) <= 1 ? static_cast<float>(std::exp(-d * d / (2.0 * sigma_l * sigma_l))) : 0.0f;
    }
  }
}

void LineBandDescriptor::setImage(const cv::Mat& gray) {
  cv::Mat smooth, dx, dy;
  cv::GaussianBlur(gray, smooth, cv::Size(5, 5), 1.0);
  cv::Sobel(smooth, dx, CV_16S, 1, 0, 3);
  cv::Sobel(smooth, dy, CV_16S, 0, 1, 3);
  cv::merge(std::vector<cv::Mat>{dx, dy}, gradient_);
}

void LineBandDescriptor::describe(const cv::Point2f& start, const cv::Point2f& end, uint8_t* out) const {
  std::fill(out, out + kBytes, uint8_t{0});
  const cv::Point2f along = end - start;
  const float length = std::hypot(along.x, along.y);
  if (gradient_.empty() || !(length > 0.0f) || !std::isfinite(length)) return;
  // No segment of the image is this long; its samples would only be clamped copies.
  if (length > 2.0f * static_cast<float>(gradient_.cols + gradient_.rows)) return;
  const cv::Point2f d = along / length;      // d_L
  const cv::Point2f o(-d.y, d.x);            // d_perp
  const int samples = std::max(1, static_cast<int>(std::lround(length)));
  const cv::Point2f middle = 0.5f * (start + end);
  const float first = -0.5f * static_cast<float>(samples - 1);

  // Per row: sums of the positive and negative parts of the gradient across
  // (d_perp) and along (d_L) the line, weighted by f_g.
  std::array<std::array<float, 4>, kRows> row{};
  const int width = gradient_.cols, height = gradient_.rows;
  const auto inside = [&](const cv::Point2f& q) {
    return q.x >= 0.0f && q.y >= 0.0f && q.x <= static_cast<float>(width - 1) && q.y <= static_cast<float>(height - 1);
  };
  for (int k = 0; k < kRows; ++k) {
    const float offset = static_cast<float>(k) - 0.5f * static_cast<float>(kRows - 1);
    const cv::Point2f p0 = middle + first * d + offset * o;
    // Sums and absolute sums; positive part = (|g| + g) / 2, negative = (|g| - g) / 2
    // (branch-free: gradient signs are random to the branch predictor).
    float across = 0, across_abs = 0, along = 0, along_abs = 0;
    const auto add = [&](const cv::Vec2s& g) {
      const float g_across = g[0] * o.x + g[1] * o.y;
      const float g_along = g[0] * d.x + g[1] * d.y;
      across += g_across;
      across_abs += std::abs(g_across);
      along += g_along;
      along_abs += std::abs(g_along);
    };
    if (inside(p0) && inside(p0 + static_cast<float>(samples - 1) * d)) {
      // The whole row lies in the image (a straight run between inside ends).
      const cv::Vec2s* pixels = gradient_.ptr<cv::Vec2s>(0);
      float x = p0.x + 0.5f, y = p0.y + 0.5f;
      for (int t = 0; t < samples; ++t, x += d.x, y += d.y) {
        add(pixels[static_cast<int>(y) * width + static_cast<int>(x)]);
      }
    } else {
      cv::Point2f p = p0;
      for (int t = 0; t < samples; ++t, p += d) {
        add(gradient_.at<cv::Vec2s>(nearestClamped(p.y, height), nearestClamped(p.x, width)));
      }
    }
    const float w = 0.5f * global_weight_[k];
    row[k] = {w * (across_abs + across), w * (across_abs - across), w * (along_abs + along), w * (along_abs - along)};
  }

  // Band description: mean (0..3) and standard deviation (4..7) over the rows
  // of the band and its neighbours, each row weighted by f_l.
  std::array<std::array<float, 8>, kBands> band{};
  for (int j = 0; j < kBands; ++j) {
    const int k0 = std::max(0, (j - 1) * kBandWidth), k1 = std::min(kRows, (j + 2) * kBandWidth);
    std::array<float, 4> sum{}, sum_sq{};
    for (int k = k0; k < k1; ++k) {
      const float w = band_weight_[j][k];
      for (int c = 0; c < 4; ++c) {
        const float v = w * row[k][c];
        sum[c] += v;
        sum_sq[c] += v * v;
      }
    }
    const float inv_n = 1.0f / static_cast<float>(k1 - k0);
    for (int c = 0; c < 4; ++c) {
      const float mean = sum[c] * inv_n;
      band[j][c] = mean;
      band[j][4 + c] = std::sqrt(std::max(sum_sq[c] * inv_n - mean * mean, 0.0f));
    }
  }
  // Means and deviations normalised apart, clamped at 0.4 against non-linear
  // illumination, normalised together (Zhang & Koch 2013, after Wang et al.).
  for (const int part : {0, 4}) {
    float norm2 = 0.0f;
    for (const auto& b : band)
      for (int c = part; c < part + 4; ++c) norm2 += b[c] * b[c];
    const float inv = norm2 > 0.0f ? 1.0f / std::sqrt(norm2) : 0.0f;
    for (auto& b : band)
      for (int c = part; c < part + 4; ++c) b[c] = std::min(b[c] * inv, 0.4f);
  }
  // (The final joint normalisation scales all values alike and leaves every
  // comparison below unchanged, so it is skipped.)
  int bit = 0;
  for (const auto& [i, j] : kBandPairs) {
    for (int c = 0; c < 8; ++c, ++bit) {
      if (band[i][c] > band[j][c]) out[bit / 8] |= static_cast<uint8_t>(1u << (bit % 8));
    }
  }
}

}  // namespace lvslam::visual
