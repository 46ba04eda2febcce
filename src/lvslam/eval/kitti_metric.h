#pragma once
// The KITTI odometry metric (devkit evaluate_odometry.cpp, Geiger et al.,
// CVPR 2012): for every 10th frame and each segment length, the first frame
// whose ground-truth path exceeds the length ends a segment; its error pose
// E = (P_i^-1 P_j)^-1 (Q_i^-1 Q_j) gives |t(E)| / length and angle(E) / length,
// averaged over all segments of all lengths.
#include <cstddef>
#include <limits>
#include <vector>

#include <Eigen/Geometry>

namespace lvslam::eval {

// The devkit's lengths, and the short ones used for short sequences.
inline const std::vector<double> kKittiLengthsM{100, 200, 300, 400, 500, 600, 700, 800};
inline const std::vector<double> kShortLengthsM{1, 5, 10};

struct KittiMetric {
  std::vector<double> lengths_m;
  std::size_t segments = 0;
  // NaN while segments is 0.
  double translation_percent = std::numeric_limits<double>::quiet_NaN();  // mean |t(E)| / length * 100
  double rotation_deg_per_m = std::numeric_limits<double>::quiet_NaN();   // mean angle(E) / length
};

// gt[k] and est[k] are associated poses; a segment starts every `step` frames.
KittiMetric computeKittiMetric(const std::vector<Eigen::Isometry3d>& gt,
                               const std::vector<Eigen::Isometry3d>& est,
                               const std::vector<double>& lengths_m, std::size_t step = 10);

}  // namespace lvslam::eval
