#pragma once
// The visual front end's extraction step: an image in, a FeatureFrame out
// (ORB points on a grid + LSD/LBD lines), with every coordinate also
// undistorted through the camera model.
#include <memory>

#include "lvslam/core/camera.h"
#include "lvslam/core/image_frame.h"
#include "lvslam/visual/feature/feature_frame.h"
#include "lvslam/visual/feature/line_extractor.h"
#include "lvslam/visual/feature/orb_extractor.h"

namespace lvslam::visual {

struct FeatureExtractorConfig {
  OrbExtractorConfig orb;
  LineExtractorConfig lines;
  bool extract_lines = true;
};

class FeatureExtractor {
 public:
  FeatureExtractor(const FeatureExtractorConfig& config, const PinholeCamera& camera);

  // Image: 8-bit gray or BGR of the camera's size; throws lvslam::Error otherwise.
  FeatureFrame extract(const ImageFrame& frame);

  const PinholeCamera& camera() const { return camera_; }

 private:
  FeatureExtractorConfig config_;
  PinholeCamera camera_;
  OrbExtractor orb_;
  std::unique_ptr<LineExtractor> lines_;
  cv::Mat gray_;  // reused conversion buffer
};

}  // namespace lvslam::visual
