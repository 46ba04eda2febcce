#pragma once
// Monocular two-view map initialisation (ORB-SLAM's initializer, with
// OpenCV's solvers): a homography and an essential matrix are estimated in
// parallel from matched keypoints, the model is selected by the ratio of
// their symmetric transfer scores (R_H > 0.45: homography), the motion
// hypotheses are tested by triangulating every inlier (cheirality,
// reprojection, parallax) and only an unambiguous winner is accepted.
//
// Scale: monocular geometry fixes the map only up to scale. Depth hints for
// features of the first view (metric depths the fusion framework reads from
// LiDAR) make the result metric; without them the median depth is set to 1.
// Hints also resolve ambiguous hypotheses (a plane's two-fold homography
// ambiguity): the structure the hints agree with, up to one scale, wins.
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "lvslam/visual/initialize/two_view_geometry.h"
#include "lvslam/visual/residuals/pose_block.h"

namespace lvslam::visual {

struct TwoViewInitializerConfig {
  double sigma_px = 1.0;           // keypoint noise; thresholds are chi2 multiples of sigma^2
  double homography_ratio = 0.45;  // ORB-SLAM's R_H threshold
  double min_parallax_deg = 1.0;
  int min_triangulated = 50;
  // The runner-up motion hypothesis must have fewer good points than this
  // times the best one (ORB-SLAM: 0.7 for the essential/fundamental matrix,
  // 0.75 for the homography, whose two-fold planar ambiguity is common).
  double ambiguity_ratio_essential = 0.7;
  double ambiguity_ratio_homography = 0.75;
  int min_depth_hints = 5;       // fewer usable hints: no metric scale
};

struct TwoViewMatch {
  int index1 = -1, index2 = -1;  // keypoint indices in view 1 and view 2
};

// Metric depth (z in camera 1) of keypoint `index1` of the first view.
struct DepthHint {
  int index1 = -1;
  double depth = 0.0;
};

struct TwoViewInitialization {
  Eigen::Isometry3d T_c2_c1 = Eigen::Isometry3d::Identity();  // view 1 is the world frame
  std::vector<Eigen::Vector3d> points_c1;  // per match; valid where triangulated
  std::vector<bool> triangulated;          // per match
  int num_triangulated = 0;
  bool used_homography = false;
  bool metric = false;  // scale from depth hints (else median depth = 1)
  double median_parallax_deg = 0.0;
};

class TwoViewInitializer {
 public:
  TwoViewInitializer(const TwoViewInitializerConfig& config, const PinholeIntrinsics& intrinsics);

  // Filled by the fusion framework from LiDAR depth before initialize().
  void setDepthHints(std::vector<DepthHint> hints) { hints_ = std::move(hints); }
  void clearDepthHints() { hints_.clear(); }

  // points1/points2: undistorted pixels of the two views' keypoints. None when
  // the views do not allow a well-posed initialisation (too few matches,
  // too little parallax, ambiguous motion). Throws lvslam::Error on a match
  // index out of range.
  std::optional<TwoViewInitialization> initialize(const std::vector<Eigen::Vector2d>& points1,
                                                  const std::vector<Eigen::Vector2d>& points2,
                                                  const std::vector<TwoViewMatch>& matches) const;

 private:
  struct ModelSelection {
    bool homography = false;
    std::vector<MotionHypothesis> hypotheses;
    std::vector<bool> inliers;  // per match, of the chosen model
  };
  static std::optional<ModelSelection> selectModel(const Eigen::Matrix3d& K, const std::vector<Eigen::Vector2d>& x1,
                                                   const std::vector<Eigen::Vector2d>& x2,
                                                   const TwoViewInitializerConfig& config);
  // The hypothesis with the most good points if it is unambiguous or the
  // depth hints single it out.
  std::optional<size_t> chooseHypothesis(const std::vector<MotionHypothesisCheck>& checks,
                                         const ModelSelection& model, const std::vector<TwoViewMatch>& matches) const;

  TwoViewInitializerConfig config_;
  PinholeIntrinsics K_;
  std::vector<DepthHint> hints_;
};

}  // namespace lvslam::visual
