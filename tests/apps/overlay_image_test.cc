// The picture of `lvslam overlay` (apps/overlay_image.h).
#include "overlay_image.h"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

namespace lvslam::apps {
namespace {

TEST(OverlayImage, DrawsLinearFeaturesRed) {
  // A pole 4 m ahead of the camera (f = 400 px, principal point (320, 240)):
  // linear LiDAR features along it, in the camera frame.
  const PinholeCamera camera(640, 480, 400.0, 400.0, 320.0, 240.0);
  std::vector<fusion::SphereFeature> pole;
  for (double y = -1.5; y <= 1.5; y += 0.01) {
    fusion::SphereFeature f;
    f.p_camera = Eigen::Vector3d(1.0, y, 4.0);
    f.direction_camera = Eigen::Vector3d::UnitY();
    f.shape = fusion::FeatureShape::kLinear;
    pole.push_back(f);
  }
  const cv::Mat gray(480, 640, CV_8UC1, cv::Scalar(0));
  const cv::Mat img = drawOverlayImage(gray, camera, pole, {}, {});
  ASSERT_EQ(img.type(), CV_8UC3);
  cv::Mat channels[3];
  cv::split(img, channels);
  EXPECT_GT(cv::countNonZero(channels[2]), 50);  // linear points are red
  EXPECT_EQ(cv::countNonZero(channels[1]), 0);   // no planar points given
}

}  // namespace
}  // namespace lvslam::apps
