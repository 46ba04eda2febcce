#pragma once
// Brightness (mean) and contrast (standard deviation) of an image, the
// figures the detection module reads, and whether the visual front end can
// use the image at all (black, saturated or featureless frames cannot be).
#include <opencv2/core.hpp>

namespace lvslam::visual {

struct ImageStatistics {
  double brightness = 0.0;  // mean gray value, 0..255
  double contrast = 0.0;    // standard deviation of the gray values
};

struct ImageUsabilityConfig {
  double min_brightness = 10.0;   // darker: a black or night-blind frame
  double max_brightness = 245.0;  // brighter: saturated
  double min_contrast = 5.0;      // flatter: nothing to detect
};

// Gray or BGR 8-bit image; an empty image gives zeros.
ImageStatistics imageStatistics(const cv::Mat& image);

bool isUsable(const ImageStatistics& stats, const ImageUsabilityConfig& config);

}  // namespace lvslam::visual
