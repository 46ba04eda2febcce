#include "lvslam/visual/feature/orb_corners.h"

#include <cmath>
#include <set>
#include <utility>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "lvslam/visual/feature/orb_extractor.h"
#include "visual/synthetic_images.h"

namespace lvslam::visual {
namespace {

TEST(OrbCorners, HarrisResponseIsOpenCvsCornerHarris) {
  const cv::Mat img = testing::texturedImage(160, 120, 4);
  cv::Mat reference;
  cv::cornerHarris(img, reference, 7, 3, 0.04, cv::BORDER_REFLECT_101);
  int checked = 0;
  for (int y = 10; y < 110; y += 7) {
    for (int x = 10; x < 150; x += 9) {
      const double expected = reference.at<float>(y, x);
      const double ours = harrisResponse(img, x, y);
      EXPECT_NEAR(ours, expected, 1e-4 * std::abs(expected) + 1e-9) << "at " << x << ", " << y;
      ++checked;
    }
  }
  EXPECT_GT(checked, 200);
}

TEST(OrbCorners, OrientationPointsUpTheIntensityRamp) {
  for (const double degrees : {0.0, 37.0, 90.0, 135.0, 200.0, 311.0}) {
    const double a = degrees * M_PI / 180.0;
    cv::Mat img(61, 61, CV_8UC1);
    for (int y = 0; y < img.rows; ++y) {
      for (int x = 0; x < img.cols; ++x) {
        // Brighter along (cos a, sin a) in image axes: the centroid lies that way.
        img.at<uchar>(y, x) = cv::saturate_cast<uchar>(128.0 + 3.0 * ((x - 30) * std::cos(a) + (y - 30) * std::sin(a)));
      }
    }
    const double got = intensityCentroidAngle(img, 30, 30, 15);
    const double diff = std::remainder(got - degrees, 360.0);
    EXPECT_NEAR(diff, 0.0, 0.5) << degrees << " deg gave " << got;
    EXPECT_GE(got, 0.0);
    EXPECT_LT(got, 360.0);
  }
}

// The orientation and the descriptor agree on their convention: a quarter turn
// of the image (exact, no resampling) still matches keypoints to their turned selves.
TEST(OrbCorners, DescriptorsMatchAcrossAQuarterTurn) {
  OrbExtractorConfig config;
  config.max_features = 500;
  OrbExtractor orb(config);
  const cv::Mat img = testing::texturedImage(400, 300, 11);
  cv::Mat turned;
  cv::rotate(img, turned, cv::ROTATE_90_CLOCKWISE);  // (x, y) -> (rows - 1 - y, x)
  std::vector<cv::KeyPoint> a, b;
  cv::Mat da, db;
  orb.extract(img, a, da);
  orb.extract(turned, b, db);
  ASSERT_GT(a.size(), 300u);
  cv::BFMatcher matcher(cv::NORM_HAMMING, true);
  std::vector<cv::DMatch> matches;
  matcher.match(da, db, matches);
  int close = 0, right = 0;
  for (const cv::DMatch& m : matches) {
    if (m.distance > 40) continue;
    ++close;
    const cv::Point2f& p = a[m.queryIdx].pt;
    const cv::Point2f expected(static_cast<float>(img.rows - 1) - p.y, p.x);
    if (cv::norm(b[m.trainIdx].pt - expected) < 3.0f * std::pow(1.2f, a[m.queryIdx].octave)) ++right;
  }
  EXPECT_GT(close, 150);
  EXPECT_GT(right, 0.9 * close) << right << " of " << close;
}

// Each level is searched at a higher FAST threshold first when that filled
// its FAST-score cut on the last image. On a textured image (strong corners
// fill the cut) and a faint one (none reach 20 grey levels), in an order that
// passes through every choice of first search, the keypoints are the ones a
// single search at fast_threshold gives.
TEST(OrbCorners, TheCheaperFirstSearchKeepsTheCornersOfTheFullSearch) {
  constexpr int kFeatures = 40;
  OrbExtractorConfig config;
  config.num_levels = 1;
  config.candidate_factor = 1.0;  // every candidate is kept: the output is the level's cut
  config.max_features = kFeatures;
  config.fast_threshold = 7;
  OrbExtractor orb(config);
  const auto fullSearch = [&](const cv::Mat& img) {
    std::vector<cv::KeyPoint> corners;
    cv::FAST(img, corners, config.fast_threshold, true, cv::FastFeatureDetector::TYPE_9_16);
    const int b = config.edge_threshold;
    std::erase_if(corners, [&](const cv::KeyPoint& kp) {
      return kp.pt.x < b || kp.pt.y < b || kp.pt.x >= img.cols - b || kp.pt.y >= img.rows - b;
    });
    cv::KeyPointsFilter::retainBest(corners, 2 * kFeatures);
    for (cv::KeyPoint& kp : corners) kp.response = harrisResponse(img, cvRound(kp.pt.x), cvRound(kp.pt.y));
    cv::KeyPointsFilter::retainBest(corners, kFeatures);
    std::set<std::pair<int, int>> at;
    for (const cv::KeyPoint& kp : corners) at.emplace(cvRound(kp.pt.x), cvRound(kp.pt.y));
    return at;
  };
  const cv::Mat textured = testing::texturedImage(640, 480, 5);
  cv::Mat faint;
  textured.convertTo(faint, CV_8U, 0.07, 128.0 * (1.0 - 0.07));  // no difference reaches 20 grey levels
  std::vector<cv::KeyPoint> strong;
  cv::FAST(textured, strong, 20, true, cv::FastFeatureDetector::TYPE_9_16);
  ASSERT_GT(strong.size(), 4u * kFeatures);  // the textured image's strong corners fill the cut
  for (const cv::Mat& img : {textured, faint, textured, textured, faint}) {
    std::vector<cv::KeyPoint> keypoints;
    cv::Mat descriptors;
    orb.extract(img, keypoints, descriptors);
    std::set<std::pair<int, int>> at;
    for (const cv::KeyPoint& kp : keypoints) at.emplace(cvRound(kp.pt.x), cvRound(kp.pt.y));
    const std::set<std::pair<int, int>> expected = fullSearch(img);
    EXPECT_EQ(static_cast<int>(expected.size()), kFeatures);
    EXPECT_EQ(at, expected);
  }
}

}  // namespace
}  // namespace lvslam::visual
