#pragma once
// Relative pose error as evo's RPE computes it: consecutive pose pairs one
// path length `delta` apart (on the estimate's path by default, as evo), error pose E = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j) for
// ground truth Q and estimate P, no alignment (Sturm et al., IROS 2012).
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/eval/error_statistics.h"

namespace lvslam::eval {

using PoseIndexPair = std::pair<std::size_t, std::size_t>;

// evo's filters.filter_pairs_by_path with all_pairs false: walking along the
// path, a pose is marked each time the distance since the last mark (or since
// pose 0) reaches delta_m; pose 0 itself is not marked. Pairs are consecutive
// marks, so a path shorter than 2 * delta_m has none.
std::vector<PoseIndexPair> consecutivePairsByPath(const std::vector<Eigen::Isometry3d>& poses,
                                                  double delta_m);

// Whose path length picks the pairs. evo chooses them on the estimate unless
// asked for pairs_from_reference, and its published figures use that default.
enum class RpePairsOn { kEstimate, kGroundTruth };

// "est", "gt".
std::string rpePairsOnName(RpePairsOn pairs_on);

struct RpeResult {
  double delta_m = 0.0;
  RpePairsOn pairs_on = RpePairsOn::kEstimate;
  std::vector<PoseIndexPair> pairs;
  std::vector<double> translation_errors;  // metres, |t(E)|
  std::vector<double> rotation_errors_deg;  // rotation angle of E
  ErrorStatistics translation;
  ErrorStatistics rotation_deg;
};

// gt[k] and est[k] are associated poses.
RpeResult computeRpe(const std::vector<Eigen::Isometry3d>& gt,
                     const std::vector<Eigen::Isometry3d>& est, double delta_m,
                     RpePairsOn pairs_on = RpePairsOn::kEstimate);

}  // namespace lvslam::eval
