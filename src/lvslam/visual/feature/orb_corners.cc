#include "lvslam/visual/feature/orb_corners.h"

#include <cmath>

namespace lvslam::visual {

namespace {
constexpr int kHarrisBlock = 7;
constexpr float kHarrisK = 0.04f;
}  // namespace

float harrisResponse(const cv::Mat& image, int x, int y) {
  const int half = kHarrisBlock / 2;
  const int step = static_cast<int>(image.step1());
  // Sums of Ix^2, Iy^2 and Ix Iy stay below 2^31 (1020^2 * 49).
  int a = 0, b = 0, c = 0;
  for (int v = -half; v <= half; ++v) {
    const uchar* p = image.ptr<uchar>(y + v) + x - half;
    for (int u = 0; u < kHarrisBlock; ++u, ++p) {
      const int ix = (p[1] - p[-1]) * 2 + (p[-step + 1] - p[-step - 1]) + (p[step + 1] - p[step - 1]);
      const int iy = (p[step] - p[-step]) * 2 + (p[step - 1] - p[-step - 1]) + (p[step + 1] - p[-step + 1]);
      a += ix * ix;
      b += iy * iy;
      c += ix * iy;
    }
  }
  // Scaled as cv::cornerHarris does and evaluated in float, as cv::ORB ranks.
  constexpr float kScale = 1.0f / (4.0f * kHarrisBlock * 255.0f);
  constexpr float kScale4 = kScale * kScale * kScale * kScale;
  const float fa = static_cast<float>(a), fb = static_cast<float>(b), fc = static_cast<float>(c);
  return (fa * fb - fc * fc - kHarrisK * (fa + fb) * (fa + fb)) * kScale4;
}

float intensityCentroidAngle(const cv::Mat& image, int x, int y, int radius) {
  // Rublee et al. 2011, Eq. 2-3: m_pq = sum x^p y^q I(x, y), theta = atan2(m01, m10).
  // The disc u^2 + v^2 <= r^2 + r is symmetric under swapping u and v, so a
  // ramp's centroid points exactly up the ramp.
  const int limit = radius * radius + radius;
  // |m10|, |m01| < r * 255 * (2r + 1)^2: int holds them for any ORB patch.
  int m10 = 0, m01 = 0;
  const auto halfWidth = [limit](int v) {
    int w = static_cast<int>(std::sqrt(static_cast<double>(limit - v * v)));
    while (w * w > limit - v * v) --w;
    while ((w + 1) * (w + 1) <= limit - v * v) ++w;
    return w;
  };
  const uchar* centre = image.ptr<uchar>(y) + x;
  for (int u = -radius; u <= radius; ++u) m10 += u * centre[u];
  // Rows v and -v together: their sum weighs u, their difference v.
  for (int v = 1; v <= radius; ++v) {
    const int w = halfWidth(v);
    const uchar* below = image.ptr<uchar>(y + v) + x;
    const uchar* above = image.ptr<uchar>(y - v) + x;
    int difference = 0;
    for (int u = -w; u <= w; ++u) {
      m10 += u * (below[u] + above[u]);
      difference += below[u] - above[u];
    }
    m01 += v * difference;
  }
  // cv::fastAtan2 (degrees in [0, 360), ~0.01 deg) as cv::ORB orients.
  return cv::fastAtan2(static_cast<float>(m01), static_cast<float>(m10));
}

}  // namespace lvslam::visual
