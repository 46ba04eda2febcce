#pragma once
#include <opencv2/core.hpp>

namespace lvslam {

// One camera image at its exposure time: 8-bit, grayscale or 3-channel BGR.
struct ImageFrame {
  double timestamp = 0.0;
  cv::Mat image;
};

}  // namespace lvslam
