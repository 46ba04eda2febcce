#include "lvslam/visual/tracking/image_statistics.h"

#include <opencv2/imgproc.hpp>

namespace lvslam::visual {

ImageStatistics imageStatistics(const cv::Mat& image) {
  ImageStatistics stats;
  if (image.empty()) return stats;
  cv::Mat gray = image;
  if (image.channels() == 3) cv::cvtColor(image, gray, cv::COLOR_BGR2GRAY);
  cv::Scalar mean, stddev;
  cv::meanStdDev(gray, mean, stddev);
  stats.brightness = mean[0];
  stats.contrast = stddev[0];
  return stats;
}

bool isUsable(const ImageStatistics& stats, const ImageUsabilityConfig& config) {
  return stats.brightness >= config.min_brightness && stats.brightness <= config.max_brightness &&
         stats.contrast >= config.min_contrast;
}

}  // namespace lvslam::visual
