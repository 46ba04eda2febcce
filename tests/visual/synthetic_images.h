#pragma once
// Deterministic synthetic images for the feature tests and benchmark.
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace lvslam::visual::testing {

// Gray image covered everywhere with random overlapping rectangles: corners
// and edges in every part of the image.
inline cv::Mat texturedImage(int width, int height, int seed = 7) {
  cv::Mat img(height, width, CV_8UC1, cv::Scalar(128));
  cv::RNG rng(static_cast<uint64_t>(seed));
  const int count = width * height / 300;
  for (int i = 0; i < count; ++i) {
    const int x = rng.uniform(-10, width), y = rng.uniform(-10, height);
    const int w = rng.uniform(4, 30), h = rng.uniform(4, 30);
    cv::rectangle(img, cv::Rect(x, y, w, h), cv::Scalar(rng.uniform(0, 256)), cv::FILLED);
  }
  return img;
}

}  // namespace lvslam::visual::testing
