#pragma once
// LSD line segments with Structure PLP-SLAM's tuned detector parameters and
// length rejection (Cao et al., Sec. III-D "Line detection"; Shu et al. 2023),
// described by LBD binary descriptors for matching.
#include <memory>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "lvslam/visual/feature/line_band_descriptor.h"

namespace lvslam::visual {

struct LineExtractorConfig {
  // LSD parameters as tuned in Structure PLP-SLAM (OpenCV defaults in brackets).
  double scale = 0.5;        // [0.8] image scale LSD runs at: faster, fewer tiny segments
  double sigma_scale = 0.6;  // [0.6]
  double quant = 2.0;        // [2.0]
  double angle_threshold_deg = 22.5;  // [22.5]
  double density_threshold = 0.6;     // [0.7]
  int n_bins = 1024;                  // [1024]
  // Segments shorter than this fraction of min(width, height) are rejected.
  double min_length_ratio = 0.125;
  int max_lines = 150;  // longest kept; bounds LBD and matching cost
  // Pyramid octave (half resolution per octave) LBD describes the segments
  // on (line_band_descriptor.h). Full resolution is the default the system
  // tests and benchmarks run with.
  int descriptor_octave = 0;
  bool compute_descriptors = true;
};

// A raw segment in the pixels of the image it was detected on.
struct RawSegment {
  cv::Point2f start, end;
  float length = 0.0f;
};

class LineExtractor {
 public:
  explicit LineExtractor(const LineExtractorConfig& config);
  ~LineExtractor();
  LineExtractor(const LineExtractor&) = delete;
  LineExtractor& operator=(const LineExtractor&) = delete;

  // gray: 8-bit single channel. Segments longest first; descriptors
  // segments.size() x 32 CV_8U (empty when compute_descriptors is off).
  void extract(const cv::Mat& gray, std::vector<RawSegment>& segments, cv::Mat& descriptors);

  const LineExtractorConfig& config() const { return config_; }

 private:
  LineExtractorConfig config_;
  cv::Ptr<cv::LineSegmentDetector> lsd_;
  std::unique_ptr<LineBandDescriptor> lbd_;
};

}  // namespace lvslam::visual
