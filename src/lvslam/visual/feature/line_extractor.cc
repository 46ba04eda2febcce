#include "lvslam/visual/feature/line_extractor.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <opencv2/line_descriptor.hpp>

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

cv::line_descriptor::KeyLine toKeyLine(const RawSegment& s, int id, int octave) {
  // LBD's pyramid halves each octave (reductionRatio 2).
  const float scale = 1.0f / static_cast<float>(1 << octave);
  cv::line_descriptor::KeyLine kl;
  kl.startPointX = s.start.x;
  kl.startPointY = s.start.y;
  kl.endPointX = s.end.x;
  kl.endPointY = s.end.y;
  kl.sPointInOctaveX = scale * s.start.x;
  kl.sPointInOctaveY = scale * s.start.y;
  kl.ePointInOctaveX = scale * s.end.x;
  kl.ePointInOctaveY = scale * s.end.y;
  kl.lineLength = scale * s.length;
  kl.numOfPixels = std::max(1, static_cast<int>(std::lround(scale * s.length)));
  kl.angle = std::atan2(s.end.y - s.start.y, s.end.x - s.start.x);
  kl.pt = 0.5f * (s.start + s.end);
  kl.octave = octave;
  kl.class_id = id;
  kl.response = 0.0f;
  kl.size = 0.0f;
  return kl;
}
}  // namespace

LineExtractor::LineExtractor(const LineExtractorConfig& config) : config_(config) {
  validate(config_);
  // log_eps only matters for LSD_REFINE_ADV; Structure PLP refines with STD.
  lsd_ = cv::createLineSegmentDetector(cv::LSD_REFINE_STD, config_.scale, config_.sigma_scale,
                                       config_.quant, config_.angle_threshold_deg, 0.0,
                                       config_.density_threshold, config_.n_bins);
  if (config_.compute_descriptors) {
    lbd_ = cv::line_descriptor::BinaryDescriptor::createBinaryDescriptor();
  }
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
  std::vector<cv::line_descriptor::KeyLine> keylines;
  keylines.reserve(segments.size());
  for (size_t i = 0; i < segments.size(); ++i) {
    keylines.push_back(toKeyLine(segments[i], static_cast<int>(i), config_.descriptor_octave));
  }
  cv::Mat computed;
  lbd_->compute(gray, keylines, computed);
  if (computed.rows != static_cast<int>(keylines.size()) || keylines.size() != segments.size()) {
    throw Error("LineExtractor", "LBD returned " + std::to_string(computed.rows) +
                                     " descriptors for " + std::to_string(segments.size()) +
                                     " segments");
  }
  // Rows follow the keylines, which LBD may regroup; class_id is our index.
  descriptors.create(computed.rows, computed.cols, computed.type());
  for (size_t i = 0; i < keylines.size(); ++i) {
    if (keylines[i].class_id < 0 || keylines[i].class_id >= computed.rows) {
      throw Error("LineExtractor", "LBD changed a keyline's class_id");
    }
    computed.row(static_cast<int>(i)).copyTo(descriptors.row(keylines[i].class_id));
  }
}

}  // namespace lvslam::visual
