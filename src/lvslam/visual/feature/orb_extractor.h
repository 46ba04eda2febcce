#pragma once
// ORB keypoints over a scale pyramid, spread evenly over the image with a
// grid (the role of ORB-SLAM's quadtree distribution): cells are served
// round-robin, each giving its strongest remaining corner, until the budget
// is spent. Textured cells cannot starve the rest of the image.
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>

#include "lvslam/visual/feature/feature_frame.h"

namespace lvslam::visual {

struct OrbExtractorConfig {
  int max_features = 1000;
  double scale_factor = 1.2;
  int num_levels = 8;
  // FAST threshold; low so that weak-texture cells still give corners (ORB-SLAM's
  // minThFAST); the grid keeps the strongest per cell.
  int fast_threshold = 7;
  // Candidates detected before the grid selection, as a multiple of max_features.
  double candidate_factor = 10.0;
  int grid_cell_size = 40;  // pixels
  int edge_threshold = 19;  // pixels of every level without corners (>= 15, ORB's patch radius)
};

class OrbExtractor {
 public:
  explicit OrbExtractor(const OrbExtractorConfig& config);

  // gray: 8-bit single channel. Keypoints in level-0 pixels; descriptors N x 32.
  // The output depends on the image only; what the last image's levels were
  // like only chooses the cheaper FAST search to try first.
  void extract(const cv::Mat& gray, std::vector<cv::KeyPoint>& keypoints, cv::Mat& descriptors);

  const ScalePyramid& pyramid() const { return pyramid_; }
  const OrbExtractorConfig& config() const { return config_; }

 private:
  OrbExtractorConfig config_;
  cv::Ptr<cv::ORB> orb_;  // describes the chosen keypoints
  ScalePyramid pyramid_;
  std::vector<int> budget_;         // candidates per level
  std::vector<float> level_scale_;  // as cv::ORB computes them
  std::vector<char> strong_fills_;  // per level: did the strong corners fill the FAST cut last time
};

// Indices of at most max_count keypoints chosen round-robin over grid cells
// (strongest response first within a cell). Deterministic.
std::vector<int> selectOnGrid(const std::vector<cv::KeyPoint>& keypoints, int width, int height,
                              int cell_size, int max_count);

}  // namespace lvslam::visual
