#include "lvslam/visual/feature/orb_extractor.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "lvslam/core/error.h"

namespace lvslam::visual {

namespace {
void validate(const OrbExtractorConfig& c) {
  const std::string where = "OrbExtractorConfig";
  if (c.max_features <= 0 || c.max_features > 100000) throw Error(where, "max_features must be in [1, 100000]");
  if (!(c.scale_factor > 1.0)) throw Error(where, "scale_factor must be > 1");
  if (c.num_levels < 1) throw Error(where, "num_levels must be >= 1");
  if (c.fast_threshold < 1) throw Error(where, "fast_threshold must be >= 1");
  if (!(c.candidate_factor >= 1.0 && c.candidate_factor <= 100.0)) throw Error(where, "candidate_factor must be in [1, 100]");
  if (c.grid_cell_size < 4) throw Error(where, "grid_cell_size must be >= 4");
  if (c.edge_threshold < 3) throw Error(where, "edge_threshold must be >= 3");
}
}  // namespace

OrbExtractor::OrbExtractor(const OrbExtractorConfig& config) : config_(config) {
  validate(config_);
  const int candidates = static_cast<int>(std::ceil(config_.max_features * config_.candidate_factor));
  orb_ = cv::ORB::create(candidates, static_cast<float>(config_.scale_factor), config_.num_levels,
                         config_.edge_threshold, 0, 2, cv::ORB::HARRIS_SCORE, 31,
                         config_.fast_threshold);
  double s = 1.0;
  for (int level = 0; level < config_.num_levels; ++level) {
    pyramid_.scale.push_back(s);
    pyramid_.inv_sigma2.push_back(1.0 / (s * s));
    s *= config_.scale_factor;
  }
}

void OrbExtractor::extract(const cv::Mat& gray, std::vector<cv::KeyPoint>& keypoints,
                           cv::Mat& descriptors) const {
  if (gray.empty() || gray.type() != CV_8UC1) {
    throw Error("OrbExtractor", "expects a non-empty 8-bit single-channel image");
  }
  // Detect generously (cv::ORB keeps the globally strongest, which starves
  // weak-texture cells), choose on the grid, then describe only the chosen.
  std::vector<cv::KeyPoint> candidates;
  orb_->detect(gray, candidates);
  const std::vector<int> keep = selectOnGrid(candidates, gray.cols, gray.rows,
                                             config_.grid_cell_size, config_.max_features);
  keypoints.clear();
  keypoints.reserve(keep.size());
  for (const int i : keep) keypoints.push_back(candidates[i]);
  orb_->compute(gray, keypoints, descriptors);
  if (descriptors.empty()) descriptors.create(0, 32, CV_8U);
}

std::vector<int> selectOnGrid(const std::vector<cv::KeyPoint>& keypoints, int width, int height,
                              int cell_size, int max_count) {
  const int cols = std::max(1, (width + cell_size - 1) / cell_size);
  const int rows = std::max(1, (height + cell_size - 1) / cell_size);
  std::vector<int> cell(keypoints.size());
  for (size_t i = 0; i < keypoints.size(); ++i) {
    const int cx = std::clamp(static_cast<int>(keypoints[i].pt.x) / cell_size, 0, cols - 1);
    const int cy = std::clamp(static_cast<int>(keypoints[i].pt.y) / cell_size, 0, rows - 1);
    cell[i] = cy * cols + cx;
  }
  std::vector<int> order(keypoints.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    if (cell[a] != cell[b]) return cell[a] < cell[b];
    return keypoints[a].response > keypoints[b].response;
  });
  // Rank of each keypoint inside its cell; round r serves every cell's r-th best.
  std::vector<int> rank(keypoints.size(), 0);
  for (size_t k = 1; k < order.size(); ++k) {
    if (cell[order[k]] == cell[order[k - 1]]) rank[order[k]] = rank[order[k - 1]] + 1;
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    if (rank[a] != rank[b]) return rank[a] < rank[b];
    return keypoints[a].response > keypoints[b].response;
  });
  if (static_cast<int>(order.size()) > max_count) order.resize(max_count);
  return order;
}

}  // namespace lvslam::visual
