#include "lvslam/core/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "lvslam/core/error.h"

namespace lvslam {
namespace {

// The M2DGR D435i with the distortion of its ORB-SLAM3 config (docs/m2dgr.md).
PinholeCamera distortedCamera() {
  return PinholeCamera(640, 480, 617.971, 616.445, 327.710, 253.977,
                       RadTanDistortion{-0.2834, 0.07396, 0.000194, 1.76e-05, 0.0});
}

TEST(PinholeCamera, ProjectsThePinholeModelExactly) {
  const PinholeCamera cam(640, 480, 500.0, 400.0, 320.0, 240.0);
  const auto px = cam.project(Eigen::Vector3d(1.0, -0.5, 2.0));
  ASSERT_TRUE(px.has_value());
  EXPECT_DOUBLE_EQ(px->x(), 320.0 + 500.0 * 0.5);
  EXPECT_DOUBLE_EQ(px->y(), 240.0 - 400.0 * 0.25);
  EXPECT_FALSE(cam.project(Eigen::Vector3d(0.0, 0.0, -1.0)).has_value());
  EXPECT_FALSE(cam.project(Eigen::Vector3d(1.0, 1.0, 0.0)).has_value());
}

TEST(PinholeCamera, ProjectUnprojectRoundTripWithDistortion) {
  const PinholeCamera cam = distortedCamera();
  for (int v = 0; v < 480; v += 37) {
    for (int u = 0; u < 640; u += 41) {
      const Eigen::Vector2d px(u, v);
      const Eigen::Vector3d ray = cam.unproject(px);
      const auto back = cam.project(3.7 * ray);
      ASSERT_TRUE(back.has_value());
      EXPECT_LT((*back - px).norm(), 1e-6) << u << "," << v;
    }
  }
}

// The simulator's distorted camera (k1 > 0, k2 < 0): its radial polynomial
// r (1 + 0.12 r^2 - 0.24 r^4) peaks at r^2 = (0.36 + sqrt(0.36^2 + 4.8)) / 2.4
// and then falls, so a point 56 deg off the axis would land 50 px right of
// the centre. It is not projected; everything up to the peak still is.
TEST(PinholeCamera, APointPastThePolynomialsFoldIsNotProjected) {
  const PinholeCamera cam(640, 480, 617.971, 616.445, 327.710, 253.976,
                          RadTanDistortion{0.12, -0.24, 0.0008, -0.0005, 0.0});
  const double r_peak = std::sqrt((0.36 + std::sqrt(0.36 * 0.36 + 4.8)) / 2.4);
  EXPECT_NEAR(cam.maxProjectableRadius(), r_peak, 2e-3);
  const Eigen::Vector3d beyond(1.5, 0.0, 1.0);
  const Eigen::Vector2d folded = cam.distortNormalized(beyond.head<2>());
  ASSERT_TRUE(cam.inImage(Eigen::Vector2d(cam.fx() * folded.x() + cam.cx(), cam.fy() * folded.y() + cam.cy())));
  EXPECT_FALSE(cam.project(beyond).has_value());
  EXPECT_TRUE(cam.project(Eigen::Vector3d(0.98 * r_peak, 0.0, 1.0)).has_value());
  // Undistorted, or distorted with a polynomial that never falls: no limit.
  EXPECT_TRUE(std::isinf(PinholeCamera(640, 480, 500.0, 500.0, 320.0, 240.0).maxProjectableRadius()));
  EXPECT_TRUE(std::isinf(distortedCamera().maxProjectableRadius()));
}

TEST(PinholeCamera, DistortionAgreesWithOpenCv) {
  const PinholeCamera cam = distortedCamera();
  const cv::Matx33d K(cam.fx(), 0, cam.cx(), 0, cam.fy(), cam.cy(), 0, 0, 1);
  const auto& d = cam.distortion();
  const std::vector<double> D{d.k1, d.k2, d.p1, d.p2, d.k3};
  const std::vector<cv::Point3d> pts{{0.3, -0.2, 1.0}, {-0.45, 0.33, 1.0}, {0.01, 0.02, 1.0}};
  std::vector<cv::Point2d> cv_px;
  cv::projectPoints(pts, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), K, D, cv_px);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto px = cam.project(Eigen::Vector3d(pts[i].x, pts[i].y, pts[i].z));
    ASSERT_TRUE(px.has_value());
    EXPECT_NEAR(px->x(), cv_px[i].x, 1e-9);
    EXPECT_NEAR(px->y(), cv_px[i].y, 1e-9);
  }
}

TEST(PinholeCamera, UndistortPointGivesTheIdealPinholePixel) {
  const PinholeCamera cam = distortedCamera();
  const Eigen::Vector3d p(0.4, -0.25, 1.3);
  const Eigen::Vector2d distorted = *cam.project(p);
  const Eigen::Vector2d ideal = *cam.projectUndistorted(p);
  EXPECT_LT((cam.undistortPoint(distorted) - ideal).norm(), 1e-6);
}

TEST(PinholeCamera, UndistortImageMovesADotToItsIdealPixel) {
  const PinholeCamera cam = distortedCamera();
  const Eigen::Vector3d p(0.35, 0.22, 1.0);  // far from the centre: large distortion
  const Eigen::Vector2d distorted = *cam.project(p);
  const Eigen::Vector2d ideal = *cam.projectUndistorted(p);
  ASSERT_GT((distorted - ideal).norm(), 5.0);
  cv::Mat img(480, 640, CV_8UC1, cv::Scalar(0));
  cv::circle(img, cv::Point(static_cast<int>(std::lround(distorted.x())), static_cast<int>(std::lround(distorted.y()))),
             3, cv::Scalar(255), cv::FILLED);
  cv::Mat out;
  cam.undistortImage(img, out);
  const cv::Moments m = cv::moments(out, false);
  ASSERT_GT(m.m00, 0.0);
  EXPECT_NEAR(m.m10 / m.m00, ideal.x(), 1.0);
  EXPECT_NEAR(m.m01 / m.m00, ideal.y(), 1.0);
}

TEST(PinholeCamera, RejectsNonPositiveFocalLength) {
  EXPECT_THROW(PinholeCamera(640, 480, 0.0, 500.0, 320.0, 240.0), Error);
  EXPECT_THROW(PinholeCamera(0, 480, 500.0, 500.0, 320.0, 240.0), Error);
}

}  // namespace
}  // namespace lvslam
