#include "lvslam/visual/feature/line_extractor.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "lvslam/core/error.h"

namespace lvslam::visual {

namespace {
void validate(const LineExtractorConfig& c) {
  const std::string where = "LineExtractorConfig";
  if (!(c.scale > 0.0 && c.scale <= 1.0)) throw Error(where, "scale must be in (0, 1]");
  if (!(c.sigma_scale > 0.0)) throw Error(where, "sigma_scale must be positive");
  if (!(c.quant > 0.0)) throw Error(where, "quant must be positive");
  if (!(c.angle_threshold_deg > 0.0 && c.angle_threshold_deg < 180.0)) {
    throw Error(where, "angle_threshold_deg must be in (0, 180)");
  }
  if (!(c.density_threshold >= 0.0 && c.density_threshold <= 1.0)) {
    throw Error(where, "density_threshold must be in [0, 1]");
  }
  if (c.n_bins < 1) throw Error(where, "n_bins must be >= 1");
  if (!(c.min_length_ratio >= 0.0 && c.min_length_ratio < 1.0)) {
    throw Error(where, "min_length_ratio must be in [0, 1)");
  }
  if (c.max_lines < 1) throw Error(where, "max_lines must be >= 1");
  if (c.descriptor_octave < 0 || c.descriptor_octave > 3) throw Error(where, "descriptor_octave must be in [0, 3]");
}

}  // namespace

LineExtractor::LineExtractor(const LineExtractorConfig& config) : config_(config) {
  validate(config_);
  // log_eps only matters for LSD_REFINE_ADV; Structure PLP refines with STD.
  lsd_ = cv::createLineSegmentDetector(cv::LSD_REFINE_STD, config_.scale, config_.sigma_scale,
                                       config_.quant, config_.angle_threshold_deg, 0.0,
                                       config_.density_threshold, config_.n_bins);
  if (config_.compute_descriptors) lbd_ = std::make_unique<LineBandDescriptor>();
}

LineExtractor::~LineExtractor() = default;

void LineExtractor::extract(const cv::Mat& gray, std::vector<RawSegment>& segments,
                            cv::Mat& descriptors) {
  if (gray.empty() || gray.type() != CV_8UC1) {
    throw Error("LineExtractor", "expects a non-empty 8-bit single-channel image");
  }
  std::vector<cv::Vec4f> detected;
  lsd_->detect(gray, detected);
  const float min_length =
      static_cast<float>(config_.min_length_ratio * std::min(gray.cols, gray.rows));
  segments.clear();
  for (const cv::Vec4f& v : detected) {
    RawSegment s{{v[0], v[1]}, {v[2], v[3]}, std::hypot(v[2] - v[0], v[3] - v[1])};
    if (std::isfinite(s.length) && s.length >= min_length) segments.push_back(s);
  }
  std::stable_sort(segments.begin(), segments.end(),
                   [](const RawSegment& a, const RawSegment& b) { return a.length > b.length; });
  if (static_cast<int>(segments.size()) > config_.max_lines) segments.resize(config_.max_lines);

  descriptors.release();
  if (!lbd_ || segments.empty()) return;
  // LBD on the chosen octave of a half-resolution pyramid (Zhang & Koch 2013).
  cv::Mat image = gray;
  for (int octave = 0; octave < config_.descriptor_octave; ++octave) cv::pyrDown(image, image);
  const float scale = 1.0f / static_cast<float>(1 << config_.descriptor_octave);
  lbd_->setImage(image);
  descriptors.create(static_cast<int>(segments.size()), LineBandDescriptor::kBytes, CV_8U);
  for (size_t i = 0; i < segments.size(); ++i) {
    lbd_->describe(scale * segments[i].start, scale * segments[i].end, descriptors.ptr<uint8_t>(static_cast<int>(i)));
  }
}

}  // namespace lvslam::visual
