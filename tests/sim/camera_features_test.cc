#include <cmath>
#include <iostream>

#include <gtest/gtest.h>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>
#include <tbb/task_arena.h>

#include "lvslam/sim/camera_renderer.h"

namespace lvslam::sim {
namespace {

int orbCorners(const cv::Mat& image) {
  std::vector<cv::KeyPoint> keypoints;
  cv::ORB::create(1200)->detect(image, keypoints);
  return static_cast<int>(keypoints.size());
}

int longSegments(const cv::Mat& image, double min_length) {
  std::vector<cv::Vec4f> lines;
  cv::createLineSegmentDetector()->detect(image, lines);
  int count = 0;
  for (const auto& l : lines)
    if (std::hypot(l[2] - l[0], l[3] - l[1]) > min_length) ++count;
  return count;
}

class CameraFeatures : public ::testing::TestWithParam<std::string> {};

// A feature SLAM needs corners and long straight segments in every scene.
TEST_P(CameraFeatures, DaytimeFramesHaveOrbCornersAndLsdSegments) {
  SimOptions options;
  options.duration = 60.0;
  const Scenario scenario = makeScenario(GetParam(), options);
  const CameraRenderer renderer(scenario);
  for (const double t : {4.0, 12.0, 21.0, 33.0, 47.0, 58.0}) {
    const cv::Mat image = renderer.renderImage(t);
    ASSERT_EQ(image.type(), CV_8UC1);
    const int corners = orbCorners(image), segments = longSegments(image, 30.0);
    std::cout << GetParam() << " t=" << t << ": ORB " << corners << " corners, LSD " << segments
              << " segments > 30 px, mean " << cv::mean(image)[0] << "\n";
    EXPECT_GT(corners, 300) << "t = " << t;
    EXPECT_GT(segments, 40) << "t = " << t;
  }
}

// Night frames are far darker than day frames of the same place.
TEST_P(CameraFeatures, NightFramesAreDark) {
  SimOptions day, night;
  day.duration = night.duration = 10.0;
  night.night = true;
  const Scenario day_scene = makeScenario(GetParam(), day), night_scene = makeScenario(GetParam(), night);
  const double day_mean = cv::mean(CameraRenderer(day_scene).renderImage(5.0))[0];
  const double night_mean = cv::mean(CameraRenderer(night_scene).renderImage(5.0))[0];
  EXPECT_LT(night_mean, 0.25 * day_mean) << "day " << day_mean << ", night " << night_mean;
}

INSTANTIATE_TEST_SUITE_P(Scenarios, CameraFeatures, ::testing::Values("room", "hall", "gate"));

// The bytes of a frame do not depend on how many threads render it.
TEST(CameraRenderer, ImageDoesNotDependOnThreadCount) {
  SimOptions options;
  options.scenario = "hall";  // with motion blur
  options.duration = 5.0;
  const Scenario scenario = makeScenario(options);
  const CameraRenderer renderer(scenario);
  const cv::Mat parallel = renderer.renderImage(3.0);
  cv::Mat serial;
  tbb::task_arena(1).execute([&] { serial = renderer.renderImage(3.0); });
  EXPECT_EQ(cv::norm(parallel, serial, cv::NORM_INF), 0.0);
}

// With lens distortion the renderer bends straight world lines exactly as the
// camera model says: a world point projects (with distortion) to where the
// depth image has that point's depth.
TEST(CameraRenderer, DistortedRenderingFollowsTheCameraModel) {
  SimOptions options;
  options.distortion = true;
  options.duration = 10.0;
  const Scenario scenario = makeScenario(options);
  ASSERT_TRUE(scenario.camera.camera.isDistorted());
  const cv::Mat depth = CameraRenderer(scenario).renderDepth(5.0);
  const Eigen::Isometry3d T_world_camera = scenario.T_world_camera(5.0);
  const PinholeCamera& cam = scenario.camera.camera;
  int checked = 0;
  for (int y = 10; y < cam.height(); y += 37)
    for (int x = 10; x < cam.width(); x += 41) {
      const Eigen::Vector3d ray = cam.unproject(Eigen::Vector2d(x, y));
      const auto hit = scenario.world.raycast(T_world_camera.translation(), T_world_camera.linear() * ray);
      ASSERT_TRUE(hit);
      const Eigen::Vector3d p_camera = ray.normalized() * hit->distance;
      EXPECT_NEAR(depth.at<float>(y, x), p_camera.z(), 1e-4);
      ++checked;
    }
  EXPECT_GT(checked, 150);
}

}  // namespace
}  // namespace lvslam::sim
