#pragma once
// Absolute trajectory error: distance between associated positions after
// aligning the estimate onto the ground truth (evo APE, translation part).
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/eval/error_statistics.h"
#include "lvslam/eval/umeyama.h"

namespace lvslam::eval {

enum class Alignment { kNone, kSE3, kSim3 };

// "none", "se3", "sim3".
std::string alignmentName(Alignment alignment);

struct AteResult {
  // Maps estimated positions into the ground-truth world (identity for kNone).
  Similarity3 T_gt_est;
  std::vector<double> errors;  // one per associated pose, metres
  ErrorStatistics stats;
};

// gt[k] and est[k] are associated poses. Throws lvslam::Error when the
// alignment is degenerate (see umeyamaAlignment).
AteResult computeAte(const std::vector<Eigen::Isometry3d>& gt,
                     const std::vector<Eigen::Isometry3d>& est, Alignment alignment);

}  // namespace lvslam::eval
