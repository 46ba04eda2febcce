#pragma once
// Pieces of two-view geometry for the initializer: DLT triangulation, the
// model scores of ORB-SLAM's model selection and the test of one motion
// hypothesis by triangulating its inliers.
#include <vector>

#include <Eigen/Core>

namespace lvslam::visual {

// Linear (DLT) triangulation from two 3x4 projection matrices and pixels /
// normalised points matching them.
Eigen::Vector3d triangulateDlt(const Eigen::Matrix<double, 3, 4>& P1, const Eigen::Matrix<double, 3, 4>& P2,
                               const Eigen::Vector2d& x1, const Eigen::Vector2d& x2);

// ORB-SLAM's scores: sum over matches of (5.991 - e^2) for each transfer error
// e^2 / sigma^2 below the chi2 gate (5.991 for H, 3.841 for F, 1 and 2 DoF),
// both directions. inliers: matches whose errors pass in both directions.
double homographyScore(const Eigen::Matrix3d& H_21, const std::vector<Eigen::Vector2d>& x1,
                       const std::vector<Eigen::Vector2d>& x2, double sigma, std::vector<bool>& inliers);
double fundamentalScore(const Eigen::Matrix3d& F_21, const std::vector<Eigen::Vector2d>& x1,
                        const std::vector<Eigen::Vector2d>& x2, double sigma, std::vector<bool>& inliers);

// A relative motion candidate: x_2 = R x_1 + t.
struct MotionHypothesis {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
};

struct MotionHypothesisCheck {
  int num_good = 0;                    // in front of both cameras, reprojecting within 2 sigma
  double median_parallax_deg = 0.0;    // over the good points
  std::vector<Eigen::Vector3d> points;  // in camera 1, per match
  std::vector<bool> triangulated;       // good and with parallax (depth is meaningful)
};

// Tests the motion (R_21, t_21) on the inlier matches (pixels, K).
MotionHypothesisCheck checkMotionHypothesis(const Eigen::Matrix3d& R_21, const Eigen::Vector3d& t_21,
                                            const Eigen::Matrix3d& K, const std::vector<Eigen::Vector2d>& x1,
                                            const std::vector<Eigen::Vector2d>& x2,
                                            const std::vector<bool>& inliers, double sigma);

}  // namespace lvslam::visual
