#pragma once
// Pinhole camera with optional radial-tangential (OpenCV k1 k2 p1 p2 k3)
// distortion. Pixel coordinates have their origin at the centre of the
// top-left pixel, as in OpenCV.
#include <array>
#include <limits>
#include <optional>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace lvslam {

struct RadTanDistortion {
  double k1 = 0.0, k2 = 0.0, p1 = 0.0, p2 = 0.0, k3 = 0.0;
  bool isZero() const { return k1 == 0.0 && k2 == 0.0 && p1 == 0.0 && p2 == 0.0 && k3 == 0.0; }
};

class PinholeCamera {
 public:
  PinholeCamera() = default;
  PinholeCamera(int width, int height, double fx, double fy, double cx, double cy,
                RadTanDistortion distortion = {});

  int width() const { return width_; }
  int height() const { return height_; }
  double fx() const { return fx_; }
  double fy() const { return fy_; }
  double cx() const { return cx_; }
  double cy() const { return cy_; }
  const RadTanDistortion& distortion() const { return distortion_; }
  bool isDistorted() const { return !distortion_.isZero(); }
  Eigen::Matrix3d K() const;

  // Point in the camera frame to a (distorted) pixel; none behind the
  // camera, nor beyond the radius where the radial polynomial stops growing
  // (past it the model folds points far outside the view back into the image).
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& p_camera) const;
  // That radius on the normalised image plane; infinite when the
  // polynomial grows everywhere (no distortion, or k1..k3 all >= 0).
  double maxProjectableRadius() const { return max_radius_; }
  // Same, for an ideal (undistorted) pinhole image.
  std::optional<Eigen::Vector2d> projectUndistorted(const Eigen::Vector3d& p_camera) const;

  // Distorted pixel to the normalised image plane point (x, y, 1).
  Eigen::Vector3d unproject(const Eigen::Vector2d& pixel) const;
  // Distorted pixel to the pixel an ideal pinhole camera with the same K sees.
  Eigen::Vector2d undistortPoint(const Eigen::Vector2d& pixel) const;

  // Applies / inverts the distortion on normalised coordinates.
  Eigen::Vector2d distortNormalized(const Eigen::Vector2d& xy) const;
  Eigen::Vector2d undistortNormalized(const Eigen::Vector2d& xy_distorted) const;

  bool inImage(const Eigen::Vector2d& pixel, double border = 0.0) const;

  // An ideal pinhole image (same K) from a distorted one, by remapping.
  // The maps are built once per camera and cached by the caller if needed.
  void undistortImage(const cv::Mat& distorted, cv::Mat& undistorted) const;

 private:
  int width_ = 0, height_ = 0;
  double fx_ = 0.0, fy_ = 0.0, cx_ = 0.0, cy_ = 0.0;
  RadTanDistortion distortion_;
  double max_radius_ = std::numeric_limits<double>::infinity();
};

}  // namespace lvslam
