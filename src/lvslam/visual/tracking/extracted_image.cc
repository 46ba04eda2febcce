#include "lvslam/visual/tracking/extracted_image.h"

namespace lvslam::visual {

ExtractedImage extractImage(FeatureExtractor& extractor, const ImageFrame& frame) {
  ExtractedImage out;
  out.timestamp = frame.timestamp;
  out.stats = imageStatistics(frame.image);
  out.features = extractor.extract(frame);
  out.features.timestamp = frame.timestamp;
  return out;
}

std::vector<ImageLineSegment> rawLineSegments(const FeatureFrame& features, const PinholeCamera& camera) {
  const auto raw = [&](const Eigen::Vector2d& px) {
    const Eigen::Vector3d ray((px.x() - camera.cx()) / camera.fx(), (px.y() - camera.cy()) / camera.fy(), 1.0);
    return camera.project(ray).value_or(px);
  };
  std::vector<ImageLineSegment> out;
  out.reserve(features.lines.size());
  for (const LineSegment& s : features.lines) out.push_back({raw(s.start), raw(s.end)});
  return out;
}

}  // namespace lvslam::visual
