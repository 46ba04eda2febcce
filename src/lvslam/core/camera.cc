#include "lvslam/core/camera.h"

#include <cmath>
#include <limits>

#include <Eigen/LU>
#include <opencv2/imgproc.hpp>

#include "lvslam/core/error.h"

namespace lvslam {

namespace {

// The first radius where r (1 + k1 r^2 + k2 r^4 + k3 r^6) stops increasing
// (its derivative 1 + 3 k1 r^2 + 5 k2 r^4 + 7 k3 r^6 reaches 0), found on a
// fine grid up to r = 20 (87 deg off the axis); infinite when there is none.
double monotonicRadius(const RadTanDistortion& d) {
  constexpr double kStep = 1e-3, kLimit = 20.0;
  for (double r = kStep; r <= kLimit; r += kStep) {
    const double r2 = r * r;
    if (1.0 + r2 * (3.0 * d.k1 + r2 * (5.0 * d.k2 + r2 * 7.0 * d.k3)) <= 0.0) return r - kStep;
  }
  return std::numeric_limits<double>::infinity();
}

}  // namespace

PinholeCamera::PinholeCamera(int width, int height, double fx, double fy, double cx, double cy,
                             RadTanDistortion distortion)
    : width_(width), height_(height), fx_(fx), fy_(fy), cx_(cx), cy_(cy), distortion_(distortion) {
  if (width <= 0 || height <= 0) throw Error("camera", "image size must be positive");
  if (!(fx > 0.0) || !(fy > 0.0) || !std::isfinite(cx) || !std::isfinite(cy))
    throw Error("camera", "intrinsics must be finite with fx, fy > 0");
  max_radius_ = monotonicRadius(distortion);
}

Eigen::Matrix3d PinholeCamera::K() const {
  Eigen::Matrix3d K;
  K << fx_, 0.0, cx_, 0.0, fy_, cy_, 0.0, 0.0, 1.0;
  return K;
}

Eigen::Vector2d PinholeCamera::distortNormalized(const Eigen::Vector2d& xy) const {
  // OpenCV's radial-tangential model (Brown-Conrady).
  const auto& d = distortion_;
  const double x = xy.x(), y = xy.y();
  const double r2 = x * x + y * y;
  const double radial = 1.0 + r2 * (d.k1 + r2 * (d.k2 + r2 * d.k3));
  return {x * radial + 2.0 * d.p1 * x * y + d.p2 * (r2 + 2.0 * x * x),
          y * radial + d.p1 * (r2 + 2.0 * y * y) + 2.0 * d.p2 * x * y};
}

Eigen::Vector2d PinholeCamera::undistortNormalized(const Eigen::Vector2d& xy_distorted) const {
  if (!isDistorted()) return xy_distorted;
  // Gauss-Newton on distort(xy) = xy_distorted with a numeric 2x2 Jacobian;
  // converges in a few steps for any lens a pinhole model is fit for.
  Eigen::Vector2d xy = xy_distorted;
  for (int it = 0; it < 20; ++it) {
    const Eigen::Vector2d r = distortNormalized(xy) - xy_distorted;
    if (r.squaredNorm() < 1e-24) break;
    constexpr double h = 1e-7;
    Eigen::Matrix2d J;
    J.col(0) = (distortNormalized(xy + Eigen::Vector2d(h, 0.0)) - distortNormalized(xy)) / h;
    J.col(1) = (distortNormalized(xy + Eigen::Vector2d(0.0, h)) - distortNormalized(xy)) / h;
    xy -= J.inverse() * r;
  }
  return xy;
}

std::optional<Eigen::Vector2d> PinholeCamera::projectUndistorted(const Eigen::Vector3d& p) const {
  if (!(p.z() > 1e-9)) return std::nullopt;
  return Eigen::Vector2d(fx_ * p.x() / p.z() + cx_, fy_ * p.y() / p.z() + cy_);
}

std::optional<Eigen::Vector2d> PinholeCamera::project(const Eigen::Vector3d& p) const {
  if (!(p.z() > 1e-9)) return std::nullopt;
  const Eigen::Vector2d xy_ideal(p.x() / p.z(), p.y() / p.z());
  if (!(xy_ideal.norm() <= max_radius_)) return std::nullopt;
  const Eigen::Vector2d xy = distortNormalized(xy_ideal);
  return Eigen::Vector2d(fx_ * xy.x() + cx_, fy_ * xy.y() + cy_);
}

Eigen::Vector3d PinholeCamera::unproject(const Eigen::Vector2d& pixel) const {
  const Eigen::Vector2d xy_d((pixel.x() - cx_) / fx_, (pixel.y() - cy_) / fy_);
  const Eigen::Vector2d xy = undistortNormalized(xy_d);
  return {xy.x(), xy.y(), 1.0};
}

Eigen::Vector2d PinholeCamera::undistortPoint(const Eigen::Vector2d& pixel) const {
  const Eigen::Vector3d n = unproject(pixel);
  return {fx_ * n.x() + cx_, fy_ * n.y() + cy_};
}

bool PinholeCamera::inImage(const Eigen::Vector2d& px, double border) const {
  return px.x() >= -0.5 + border && px.y() >= -0.5 + border && px.x() < width_ - 0.5 - border &&
         px.y() < height_ - 0.5 - border;
}

void PinholeCamera::undistortImage(const cv::Mat& distorted, cv::Mat& undistorted) const {
  if (!isDistorted()) {
    distorted.copyTo(undistorted);
    return;
  }
  // For each ideal pixel, where it lies in the distorted image.
  cv::Mat map_x(height_, width_, CV_32F), map_y(height_, width_, CV_32F);
  for (int v = 0; v < height_; ++v) {
    for (int u = 0; u < width_; ++u) {
      const Eigen::Vector2d xy((u - cx_) / fx_, (v - cy_) / fy_);
      const Eigen::Vector2d d = distortNormalized(xy);
      map_x.at<float>(v, u) = static_cast<float>(fx_ * d.x() + cx_);
      map_y.at<float>(v, u) = static_cast<float>(fy_ * d.y() + cy_);
    }
  }
  cv::remap(distorted, undistorted, map_x, map_y, cv::INTER_LINEAR, cv::BORDER_CONSTANT);
}

}  // namespace lvslam
