#pragma once
// One image after the visual front end's stateless work: brightness and
// contrast for the usability check and the detection module, and the ORB +
// LSD/LBD features. Split from tracking so that a pipeline can extract frame
// k+1 on another thread while frame k is tracked; the result does not depend
// on where it was computed.
#include <vector>

#include <Eigen/Core>

#include "lvslam/core/camera.h"
#include "lvslam/core/image_frame.h"
#include "lvslam/visual/feature/feature_extractor.h"
#include "lvslam/visual/feature/feature_frame.h"
#include "lvslam/visual/tracking/image_statistics.h"

namespace lvslam::visual {

struct ExtractedImage {
  double timestamp = 0.0;
  ImageStatistics stats;
  FeatureFrame features;
};

// Throws lvslam::Error on an image of the wrong size or type (FeatureExtractor).
ExtractedImage extractImage(FeatureExtractor& extractor, const ImageFrame& frame);

// A line segment in raw (distorted) image pixels, as the camera delivered them.
struct ImageLineSegment {
  Eigen::Vector2d start = Eigen::Vector2d::Zero(), end = Eigen::Vector2d::Zero();
};

// The frame's line segments (kept undistorted) back in raw pixels: what the
// fusion framework projects LiDAR features against. Known once extracted,
// so the fusion framework need not wait for tracking.
std::vector<ImageLineSegment> rawLineSegments(const FeatureFrame& features, const PinholeCamera& camera);

}  // namespace lvslam::visual
