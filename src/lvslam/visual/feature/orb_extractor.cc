#include "lvslam/visual/feature/orb_extractor.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <opencv2/imgproc.hpp>

#include "lvslam/core/error.h"
#include "lvslam/visual/feature/orb_corners.h"

namespace lvslam::visual {

namespace {
constexpr int kPatchSize = 31;  // ORB's descriptor patch (Rublee et al. 2011)
constexpr int kPatchRadius = kPatchSize / 2;
constexpr int kStrongFast = 20;  // FAST threshold of the cheaper first search (ORB-SLAM's iniThFAST)

void validate(const OrbExtractorConfig& c) {
  const std::string where = "OrbExtractorConfig";
  if (c.max_features <= 0 || c.max_features > 100000) throw Error(where, "max_features must be in [1, 100000]");
  if (!(c.scale_factor > 1.0)) throw Error(where, "scale_factor must be > 1");
  if (c.num_levels < 1) throw Error(where, "num_levels must be >= 1");
  if (c.fast_threshold < 1) throw Error(where, "fast_threshold must be >= 1");
  if (!(c.candidate_factor >= 1.0 && c.candidate_factor <= 100.0)) throw Error(where, "candidate_factor must be in [1, 100]");
  if (c.grid_cell_size < 4) throw Error(where, "grid_cell_size must be >= 4");
  // The orientation disc must fit inside the image around every corner.
  if (c.edge_threshold < kPatchRadius) {
    throw Error(where, "edge_threshold must be >= " + std::to_string(kPatchRadius));
  }
}

// Each level's share of the candidates, proportional to its linear size as in
// cv::ORB and ORB-SLAM (a geometric series in 1 / scale_factor); the last level
// takes what is left.
std::vector<int> candidatesPerLevel(int total, double scale_factor, int levels) {
  std::vector<int> share(levels, 0);
  const double q = 1.0 / scale_factor;
  double next = total * (1.0 - q) / (1.0 - std::pow(q, levels));
  int used = 0;
  for (int level = 0; level + 1 < levels; ++level, next *= q) {
    share[level] = static_cast<int>(std::lround(next));
    used += share[level];
  }
  share[levels - 1] = std::max(total - used, 0);
  return share;
}

// The level's FAST corners at least edge_threshold pixels inside, cut to the
// 2 * budget of highest FAST score (as cv::ORB does). A corner is suppressed
// only by a neighbour of higher score, so the corners scoring at least
// kStrongFast are the same at any lower threshold: when they fill the cut,
// a search at kStrongFast keeps exactly what the search at fast_threshold
// would, without scoring every weak corner (tens of thousands on a noisy
// night image). `strong_fills` says whether they filled it on the level's
// last image; it only decides which search is tried first.
std::vector<cv::KeyPoint> fastCut(const cv::Mat& level_image, int budget, const OrbExtractorConfig& c,
                                  char& strong_fills) {
  const auto fastInside = [&](int threshold) {
    std::vector<cv::KeyPoint> found;
    cv::FAST(level_image, found, threshold, true, cv::FastFeatureDetector::TYPE_9_16);
    const int border = c.edge_threshold;
    std::erase_if(found, [&](const cv::KeyPoint& kp) {
      const int x = cvRound(kp.pt.x), y = cvRound(kp.pt.y);
      return x < border || y < border || x >= level_image.cols - border || y >= level_image.rows - border;
    });
    return found;
  };
  const int cut = 2 * budget;
  const bool strong_first = c.fast_threshold < kStrongFast && strong_fills;
  std::vector<cv::KeyPoint> corners;
  if (strong_first) corners = fastInside(kStrongFast);
  if (!strong_first || static_cast<int>(corners.size()) < cut) corners = fastInside(c.fast_threshold);
  // FAST's response is the corner's score.
  strong_fills = std::count_if(corners.begin(), corners.end(),
                               [](const cv::KeyPoint& kp) { return kp.response >= kStrongFast; }) >= cut;
  cv::KeyPointsFilter::retainBest(corners, cut);
  return corners;
}

// The level's cut (fastCut), the strongest `budget` of it by Harris, in
// level-0 pixels; `at_level` keeps their pixels in the level image.
void detectOnLevel(const cv::Mat& level_image, int level, float scale, int budget, const OrbExtractorConfig& c,
                   char& strong_fills, std::vector<cv::KeyPoint>& candidates, std::vector<cv::Point>& at_level) {
  std::vector<cv::KeyPoint> corners = fastCut(level_image, budget, c, strong_fills);
  for (cv::KeyPoint& kp : corners) kp.response = harrisResponse(level_image, cvRound(kp.pt.x), cvRound(kp.pt.y));
  cv::KeyPointsFilter::retainBest(corners, budget);
  for (const cv::KeyPoint& kp : corners) {
    const int x = cvRound(kp.pt.x), y = cvRound(kp.pt.y);
    candidates.emplace_back(kp.pt * scale, static_cast<float>(kPatchSize) * scale, -1.0f, kp.response, level);
    at_level.emplace_back(x, y);
  }
}
}  // namespace

OrbExtractor::OrbExtractor(const OrbExtractorConfig& config) : config_(config) {
  validate(config_);
  // Used only to describe the chosen keypoints; its detector settings are unused.
  orb_ = cv::ORB::create(config_.max_features, static_cast<float>(config_.scale_factor), config_.num_levels,
                         config_.edge_threshold, 0, 2, cv::ORB::HARRIS_SCORE, kPatchSize,
                         config_.fast_threshold);
  const int total = static_cast<int>(std::ceil(config_.max_features * config_.candidate_factor));
  budget_ = candidatesPerLevel(total, config_.scale_factor, config_.num_levels);
  strong_fills_.assign(static_cast<std::size_t>(config_.num_levels), 1);
  // cv::ORB's level scales (float, from its float factor): the keypoints land
  // on the pixels it describes.
  const double factor = static_cast<float>(config_.scale_factor);
  for (int level = 0; level < config_.num_levels; ++level) {
    level_scale_.push_back(static_cast<float>(std::pow(factor, level)));
  }
  double s = 1.0;
  for (int level = 0; level < config_.num_levels; ++level) {
    pyramid_.scale.push_back(s);
    pyramid_.inv_sigma2.push_back(1.0 / (s * s));
    s *= config_.scale_factor;
  }
}

void OrbExtractor::extract(const cv::Mat& gray, std::vector<cv::KeyPoint>& keypoints,
                           cv::Mat& descriptors) {
  if (gray.empty() || gray.type() != CV_8UC1) {
    throw Error("OrbExtractor", "expects a non-empty 8-bit single-channel image");
  }
  // Detect generously on every level (the strongest only would starve
  // weak-texture cells), choose on the grid, then orient and describe only
  // the chosen.
  std::vector<cv::Mat> levels(config_.num_levels);
  std::vector<cv::KeyPoint> candidates;
  std::vector<cv::Point> at_level;
  for (int level = 0; level < config_.num_levels; ++level) {
    const float s = level_scale_[level];
    if (level == 0) {
      levels[0] = gray;
    } else {
      const cv::Size size(cvRound(static_cast<float>(gray.cols) / s), cvRound(static_cast<float>(gray.rows) / s));
      if (size.width <= 2 * config_.edge_threshold || size.height <= 2 * config_.edge_threshold) break;
      cv::resize(levels[level - 1], levels[level], size, 0, 0, cv::INTER_LINEAR_EXACT);
    }
    detectOnLevel(levels[level], level, s, budget_[level], config_, strong_fills_[level], candidates, at_level);
  }
  const std::vector<int> keep = selectOnGrid(candidates, gray.cols, gray.rows,
                                             config_.grid_cell_size, config_.max_features);
  keypoints.clear();
  keypoints.reserve(keep.size());
  for (const int i : keep) {
    cv::KeyPoint kp = candidates[i];
    kp.angle = intensityCentroidAngle(levels[kp.octave], at_level[i].x, at_level[i].y, kPatchRadius);
    keypoints.push_back(kp);
  }
  // cv::ORB regroups the keypoints by level; descriptor rows follow the output order.
  orb_->compute(gray, keypoints, descriptors);
  if (descriptors.empty()) descriptors.create(0, 32, CV_8U);
}

std::vector<int> selectOnGrid(const std::vector<cv::KeyPoint>& keypoints, int width, int height,
                              int cell_size, int max_count) {
  const int cols = std::max(1, (width + cell_size - 1) / cell_size);
  const int rows = std::max(1, (height + cell_size - 1) / cell_size);
  std::vector<std::vector<int>> cells(static_cast<size_t>(cols) * rows);
  for (size_t i = 0; i < keypoints.size(); ++i) {
    const int cx = std::clamp(static_cast<int>(keypoints[i].pt.x) / cell_size, 0, cols - 1);
    const int cy = std::clamp(static_cast<int>(keypoints[i].pt.y) / cell_size, 0, rows - 1);
    cells[cy * cols + cx].push_back(static_cast<int>(i));
  }
  const auto stronger = [&](int a, int b) { return keypoints[a].response > keypoints[b].response; };
  for (std::vector<int>& cell : cells) std::stable_sort(cell.begin(), cell.end(), stronger);
  // Round r serves every cell's r-th best, strongest first; ties keep cell order.
  std::vector<int> chosen;
  std::vector<int> round;
  for (size_t r = 0; static_cast<int>(chosen.size()) < max_count; ++r) {
    round.clear();
    for (const std::vector<int>& cell : cells) {
      if (r < cell.size()) round.push_back(cell[r]);
    }
    if (round.empty()) break;
    std::stable_sort(round.begin(), round.end(), stronger);
    const size_t room = static_cast<size_t>(max_count) - chosen.size();
    chosen.insert(chosen.end(), round.begin(), round.begin() + std::min(room, round.size()));
  }
  return chosen;
}

}  // namespace lvslam::visual
