#include "lvslam/visual/feature/feature_extractor.h"

#include <string>

#include <opencv2/imgproc.hpp>
#include <tbb/parallel_invoke.h>

#include "lvslam/core/error.h"

namespace lvslam::visual {

FeatureExtractor::FeatureExtractor(const FeatureExtractorConfig& config, const PinholeCamera& camera)
    : config_(config), camera_(camera), orb_(config.orb) {
  if (camera_.width() <= 0 || camera_.height() <= 0) {
    throw Error("FeatureExtractor", "camera has no image size");
  }
  if (config_.extract_lines) lines_ = std::make_unique<LineExtractor>(config_.lines);
}

FeatureFrame FeatureExtractor::extract(const ImageFrame& frame) {
  const cv::Mat& image = frame.image;
  if (image.empty()) throw Error("FeatureExtractor", "empty image at t=" + std::to_string(frame.timestamp));
  if (image.cols != camera_.width() || image.rows != camera_.height()) {
    throw Error("FeatureExtractor", "image is " + std::to_string(image.cols) + "x" +
                                        std::to_string(image.rows) + ", camera is " +
                                        std::to_string(camera_.width()) + "x" +
                                        std::to_string(camera_.height()));
  }
  if (image.type() == CV_8UC3) {
    cv::cvtColor(image, gray_, cv::COLOR_BGR2GRAY);
  } else if (image.type() == CV_8UC1) {
    gray_ = image;
  } else {
    throw Error("FeatureExtractor", "image must be 8-bit gray or BGR");
  }

  FeatureFrame out;
  out.timestamp = frame.timestamp;
  out.width = image.cols;
  out.height = image.rows;
  out.pyramid = orb_.pyramid();
  // ORB and LSD/LBD read the same gray image and share nothing else: they run
  // side by side (one after the other when TBB is limited to one thread).
  std::vector<RawSegment> segments;
  tbb::parallel_invoke([&] { orb_.extract(gray_, out.keypoints, out.descriptors); },
                       [&] {
                         if (lines_) lines_->extract(gray_, segments, out.line_descriptors);
                       });
  out.points.reserve(out.keypoints.size());
  const bool distorted = camera_.isDistorted();
  for (const cv::KeyPoint& kp : out.keypoints) {
    const Eigen::Vector2d px(kp.pt.x, kp.pt.y);
    out.points.push_back(distorted ? camera_.undistortPoint(px) : px);
  }
  out.lines.reserve(segments.size());
  for (const RawSegment& s : segments) {
    // Endpoints undistorted; the segment between them is taken as straight
    // (exact without distortion, a small approximation with mild radtan).
    LineSegment seg;
    seg.start = Eigen::Vector2d(s.start.x, s.start.y);
    seg.end = Eigen::Vector2d(s.end.x, s.end.y);
    if (distorted) {
      seg.start = camera_.undistortPoint(seg.start);
      seg.end = camera_.undistortPoint(seg.end);
    }
    seg.coefficients = lineCoefficients(seg.start, seg.end);
    seg.length = (seg.end - seg.start).norm();
    out.lines.push_back(seg);
  }
  return out;
}

}  // namespace lvslam::visual
