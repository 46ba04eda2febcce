#pragma once
// LBD, the line band descriptor (Zhang & Koch 2013), in binary form: the
// segment's support region is cut into bands parallel to it; each band is
// described by the mean and spread of its rows' gradient sums along and
// across the line; bits compare bands pairwise. Written for speed: one
// gradient image per frame and nearest-pixel samples (OpenCV's LBD was a
// large share of the visual front end's time; docs/architecture.md).
#include <array>
#include <cstdint>

#include <opencv2/core.hpp>

namespace lvslam::visual {

class LineBandDescriptor {
 public:
  static constexpr int kBands = 9;      // m (Zhang & Koch 2013)
  static constexpr int kBandWidth = 7;  // w, pixels
  static constexpr int kRows = kBands * kBandWidth;
  static constexpr int kBytes = 32;

  LineBandDescriptor();

  // Smoothed 3x3 Sobel gradients of the 8-bit image the segments lie in.
  void setImage(const cv::Mat& gray);
  // The 256-bit descriptor of the segment start -> end (pixels of that image)
  // into out[0..31]. The direction matters: LSD orients segments by their
  // gradient, so the same edge keeps its direction from frame to frame.
  // All bits zero for a degenerate segment, one far longer than the image or
  // before setImage.
  void describe(const cv::Point2f& start, const cv::Point2f& end, uint8_t* out) const;

 private:
  cv::Mat gradient_;  // CV_16SC2: (dx, dy) per pixel
  std::array<float, kRows> global_weight_;  // f_g: Gaussian across the whole region
  // f_l: weight of row k in band j's statistics, 0 outside bands j-1..j+1.
  std::array<std::array<float, kRows>, kBands> band_weight_;
};

}  // namespace lvslam::visual
