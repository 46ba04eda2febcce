#include "lvslam/fusion/debug_image.h"

#include <algorithm>

#include <opencv2/imgproc.hpp>

namespace lvslam::fusion {

namespace {

cv::Point toPoint(const Eigen::Vector2d& p) { return {static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y()))}; }

cv::Scalar featureColour(const SphereFeature& f) {
  // Near points bright, points at 30 m and beyond at a third of the brightness.
  const double shade = std::clamp(1.0 - f.p_camera.norm() / 45.0, 0.33, 1.0) * 255.0;
  switch (f.shape) {
    case FeatureShape::kPlanar: return {0, shade, 0};
    case FeatureShape::kLinear: return {0, 0, shade};
    default: return {shade, 0, 0};
  }
}

}  // namespace

cv::Mat drawFusionDebugImage(const cv::Mat& image, const PinholeCamera& camera,
                             const std::vector<SphereFeature>& features, const std::vector<ImageSegment>& segments,
                             const std::vector<FusionLine>& lines) {
  cv::Mat canvas;
  if (image.channels() == 1) {
    cv::cvtColor(image, canvas, cv::COLOR_GRAY2BGR);
  } else {
    canvas = image.clone();
  }
  for (const SphereFeature& f : features) {
    const auto px = camera.project(f.p_camera);
    if (px && camera.inImage(*px)) cv::circle(canvas, toPoint(*px), 1, featureColour(f), cv::FILLED);
  }
  for (const ImageSegment& s : segments)
    cv::line(canvas, toPoint(s.start), toPoint(s.end), cv::Scalar(0, 255, 255), 1, cv::LINE_AA);
  for (const FusionLine& l : lines) {
    const auto a = camera.project(l.A);
    const auto b = camera.project(l.B);
    if (a && b) cv::line(canvas, toPoint(*a), toPoint(*b), cv::Scalar(255, 0, 255), 2, cv::LINE_AA);
  }
  return canvas;
}

}  // namespace lvslam::fusion
