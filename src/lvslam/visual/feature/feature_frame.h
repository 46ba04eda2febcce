#pragma once
// What the visual front end keeps of one image: ORB keypoints over a scale
// pyramid and LSD line segments with LBD descriptors (Structure PLP-SLAM's
// point-line frame). Coordinates "undistorted" are pixels of the ideal
// pinhole camera with the same K.
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace lvslam::visual {

// The ORB pyramid: per level scale s^l and the inverse variance 1/(s^l)^2
// that weights a reprojection residual observed at that level (ORB-SLAM).
struct ScalePyramid {
  std::vector<double> scale;
  std::vector<double> inv_sigma2;
};

struct LineSegment {
  Eigen::Vector2d start = Eigen::Vector2d::Zero();  // undistorted pixels
  Eigen::Vector2d end = Eigen::Vector2d::Zero();
  // Image line through the endpoints, l = x_s x x_e scaled so l1^2 + l2^2 = 1:
  // l . (u, v, 1) is then the signed pixel distance to the line.
  Eigen::Vector3d coefficients = Eigen::Vector3d::Zero();
  double length = 0.0;  // pixels
};

struct FeatureFrame {
  double timestamp = 0.0;
  int width = 0, height = 0;
  std::vector<cv::KeyPoint> keypoints;   // distorted pixels; octave = pyramid level
  std::vector<Eigen::Vector2d> points;   // the keypoints, undistorted
  cv::Mat descriptors;                   // keypoints.size() x 32, CV_8U (ORB)
  std::vector<LineSegment> lines;
  cv::Mat line_descriptors;              // lines.size() x 32, CV_8U (LBD)
  ScalePyramid pyramid;
};

// Line coefficients of the segment (start, end) as defined above.
Eigen::Vector3d lineCoefficients(const Eigen::Vector2d& start, const Eigen::Vector2d& end);

}  // namespace lvslam::visual
