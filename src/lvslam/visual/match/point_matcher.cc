#include "lvslam/visual/match/point_matcher.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "lvslam/visual/match/descriptor_distance.h"
#include "lvslam/visual/match/unique_matches.h"

namespace lvslam::visual {

namespace {

constexpr int kHistogramBins = 30;

struct Best {
  int index = -1;
  int distance = std::numeric_limits<int>::max();
  int second = std::numeric_limits<int>::max();
};

Best bestCandidate(const uint8_t* query, const std::vector<int>& candidates, const cv::Mat& descriptors) {
  Best best;
  for (const int j : candidates) {
    const int d = hammingDistance256(query, descriptors.ptr<uint8_t>(j));
    if (d < best.distance) {
      best.second = best.distance;
      best.distance = d;
      best.index = j;
    } else if (d < best.second) {
      best.second = d;
    }
  }
  return best;
}

// ORB-SLAM's rotation consistency: keep matches in the three most populated
// bins of the keypoint angle difference.
std::vector<PointMatch> keepDominantRotation(const std::vector<PointMatch>& matches, const FeatureFrame& a,
                                             const FeatureFrame& b) {
  std::array<std::vector<size_t>, kHistogramBins> bins;
  for (size_t m = 0; m < matches.size(); ++m) {
    float rot = a.keypoints[matches[m].index1].angle - b.keypoints[matches[m].index2].angle;
    if (rot < 0.0f) rot += 360.0f;
    const int bin = std::min(kHistogramBins - 1, static_cast<int>(rot * kHistogramBins / 360.0f));
    bins[bin].push_back(m);
  }
  std::array<int, kHistogramBins> order{};
  for (int i = 0; i < kHistogramBins; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](int x, int y) { return bins[x].size() > bins[y].size(); });
  std::vector<bool> keep(matches.size(), false);
  for (int k = 0; k < 3; ++k) {
    // Bins much smaller than the largest are not a second mode (ORB-SLAM: < 10 %).
    if (bins[order[k]].size() < 0.1 * bins[order[0]].size()) break;
    for (const size_t m : bins[order[k]]) keep[m] = true;
  }
  std::vector<PointMatch> out;
  for (size_t m = 0; m < matches.size(); ++m) {
    if (keep[m]) out.push_back(matches[m]);
  }
  return out;
}

bool accept(const Best& best, const PointMatcherConfig& config) {
  return best.index >= 0 && best.distance <= config.max_distance &&
         (best.second == std::numeric_limits<int>::max() || best.distance < config.ratio * best.second);
}

}  // namespace

std::vector<PointMatch> matchInWindow(const FeatureFrame& a, const FeatureFrame& b, const FeatureGrid& grid_b,
                                      double window, const PointMatcherConfig& config) {
  std::vector<PointMatch> matches;
  std::vector<int> candidates;
  for (size_t i = 0; i < a.points.size(); ++i) {
    grid_b.query(a.points[i], window, candidates);
    const Best best = bestCandidate(a.descriptors.ptr<uint8_t>(static_cast<int>(i)), candidates, b.descriptors);
    if (accept(best, config)) matches.push_back({static_cast<int>(i), best.index, best.distance});
  }
  matches = uniqueMatches(std::move(matches), b.points.size());
  return config.check_orientation ? keepDominantRotation(matches, a, b) : matches;
}

std::vector<PointMatch> matchByProjection(const std::vector<ProjectedPoint>& projected, const FeatureFrame& frame,
                                          const FeatureGrid& grid, const PointMatcherConfig& config) {
  std::vector<PointMatch> matches;
  std::vector<int> candidates;
  for (size_t i = 0; i < projected.size(); ++i) {
    const ProjectedPoint& p = projected[i];
    if (p.descriptor.empty()) continue;
    grid.query(p.pixel, p.radius, candidates);
    const Best best = bestCandidate(p.descriptor.ptr<uint8_t>(0), candidates, frame.descriptors);
    if (accept(best, config)) matches.push_back({static_cast<int>(i), best.index, best.distance});
  }
  return uniqueMatches(std::move(matches), frame.points.size());
}

}  // namespace lvslam::visual
