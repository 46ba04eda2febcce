#include "overlay_image.h"

#include <algorithm>

#include <opencv2/imgproc.hpp>

namespace lvslam::apps {

namespace {

cv::Point toPoint(const Eigen::Vector2d& p) { return {static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y()))}; }

cv::Scalar featureColour(const fusion::SphereFeature& f) {
  // Near points bright, points at 30 m and beyond at a third of the brightness.
  const double shade = std::clamp(1.0 - f.p_camera.norm() / 45.0, 0.33, 1.0) * 255.0;
  switch (f.shape) {
    case fusion::FeatureShape::kPlanar: return {0, shade, 0};
    case fusion::FeatureShape::kLinear: return {0, 0, shade};
    default: return {shade, 0, 0};
  }
}

}  // namespace

cv::Mat drawOverlayImage(const cv::Mat& image, const PinholeCamera& camera,
                         const std::vector<fusion::SphereFeature>& features,
                         const std::vector<fusion::ImageSegment>& segments, const std::vector<fusion::FusionLine>& lines) {
  cv::Mat canvas;
  if (image.channels() == 1) {
    cv::cvtColor(image, canvas, cv::COLOR_GRAY2BGR);
  } else {
    canvas = image.clone();
  }
  for (const fusion::SphereFeature& f : features) {
    const auto px = camera.project(f.p_camera);
    if (px && camera.inImage(*px)) cv::circle(canvas, toPoint(*px), 1, featureColour(f), cv::FILLED);
  }
  for (const fusion::ImageSegment& s : segments)
    cv::line(canvas, toPoint(s.start), toPoint(s.end), cv::Scalar(0, 255, 255), 1, cv::LINE_AA);
  for (const fusion::FusionLine& l : lines) {
    const auto a = camera.project(l.A);
    const auto b = camera.project(l.B);
    if (a && b) cv::line(canvas, toPoint(*a), toPoint(*b), cv::Scalar(255, 0, 255), 2, cv::LINE_AA);
  }
  return canvas;
}

}  // namespace lvslam::apps
