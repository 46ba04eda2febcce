#include "lvslam/visual/feature/feature_extractor.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include <Eigen/Geometry>

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <opencv2/imgproc.hpp>

#include "lvslam/core/error.h"
#include "visual/synthetic_images.h"

namespace lvslam::visual {
namespace {

PinholeCamera vgaCamera() { return PinholeCamera(640, 480, 500.0, 500.0, 319.5, 239.5); }

double distanceToLine(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return std::abs(lineCoefficients(a, b).dot(p.homogeneous()));
}

TEST(OrbExtractor, FillsTheBudgetSpreadEvenlyOverTheGrid) {
  OrbExtractorConfig config;
  config.max_features = 600;
  config.grid_cell_size = 40;
  OrbExtractor orb(config);
  std::vector<cv::KeyPoint> kps;
  cv::Mat desc;
  orb.extract(testing::texturedImage(640, 480), kps, desc);
  ASSERT_EQ(static_cast<int>(kps.size()), config.max_features);
  ASSERT_EQ(desc.rows, config.max_features);
  ASSERT_EQ(desc.cols, 32);
  std::map<int, int> per_cell;
  std::set<int> octaves;
  for (const auto& kp : kps) {
    per_cell[static_cast<int>(kp.pt.y) / 40 * 16 + static_cast<int>(kp.pt.x) / 40]++;
    octaves.insert(kp.octave);
  }
  // 16 x 12 cells; texture everywhere, so nearly all of them get points ...
  EXPECT_GE(per_cell.size(), 0.9 * 16 * 12);
  // ... and round-robin allots at most one more than the even share to any cell.
  const int even_share = (config.max_features + static_cast<int>(per_cell.size()) - 1) /
                         static_cast<int>(per_cell.size());
  for (const auto& [cell, n] : per_cell) EXPECT_LE(n, even_share + 1) << "cell " << cell;
  EXPECT_GE(octaves.size(), 3u) << "keypoints come from several pyramid levels";
}

TEST(OrbExtractor, GridSelectionIsRoundRobinByResponse) {
  std::vector<cv::KeyPoint> kps;
  // Three points in cell 0 (strong), one in cell 1 (weak).
  kps.emplace_back(cv::Point2f(1, 1), 1.0f, -1.0f, 9.0f);
  kps.emplace_back(cv::Point2f(2, 2), 1.0f, -1.0f, 8.0f);
  kps.emplace_back(cv::Point2f(3, 3), 1.0f, -1.0f, 7.0f);
  kps.emplace_back(cv::Point2f(15, 1), 1.0f, -1.0f, 1.0f);
  const std::vector<int> pick = selectOnGrid(kps, 20, 10, 10, 2);
  ASSERT_EQ(pick.size(), 2u);
  EXPECT_EQ(pick[0], 0);
  EXPECT_EQ(pick[1], 3);  // the weak point of the other cell before the 2nd best of cell 0
}

cv::Mat rectangleImage() {
  cv::Mat img(480, 640, CV_8UC1, cv::Scalar(60));
  cv::rectangle(img, cv::Point(120, 100), cv::Point(500, 380), cv::Scalar(200), cv::FILLED);
  cv::rectangle(img, cv::Point(20, 20), cv::Point(45, 45), cv::Scalar(220), cv::FILLED);  // short edges
  return img;
}

TEST(LineExtractor, FindsEachLongEdgeAndRejectsShortOnes) {
  LineExtractor lines(LineExtractorConfig{});
  std::vector<RawSegment> segments;
  cv::Mat desc;
  lines.extract(rectangleImage(), segments, desc);
  ASSERT_EQ(desc.rows, static_cast<int>(segments.size()));
  const double min_length = 0.125 * 480;
  for (const RawSegment& s : segments) EXPECT_GE(s.length, min_length);
  // The four edges of the big rectangle, on the half-pixel boundary.
  const std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> edges = {
      {{119.5, 99.5}, {500.5, 99.5}},
      {{500.5, 99.5}, {500.5, 380.5}},
      {{500.5, 380.5}, {119.5, 380.5}},
      {{119.5, 380.5}, {119.5, 99.5}}};
  for (const auto& [a, b] : edges) {
    bool found = false;
    for (const RawSegment& s : segments) {
      const Eigen::Vector2d p(s.start.x, s.start.y), q(s.end.x, s.end.y);
      if (distanceToLine(p, a, b) < 1.5 && distanceToLine(q, a, b) < 1.5 &&
          s.length > 0.8 * (b - a).norm()) {
        found = true;
      }
    }
    EXPECT_TRUE(found) << "edge from " << a.transpose() << " to " << b.transpose();
  }
  EXPECT_LE(segments.size(), 8u);
  for (size_t i = 1; i < segments.size(); ++i) EXPECT_GE(segments[i - 1].length, segments[i].length);
}

class LbdOctave : public ::testing::TestWithParam<int> {};

// At full resolution and on LBD's half-resolution octave alike.
TEST_P(LbdOctave, LbdDescriptorsMatchTheSameLinesInAShiftedImage) {
  LineExtractorConfig config;
  config.descriptor_octave = GetParam();
  LineExtractor lines(config);
  const cv::Mat img = testing::texturedImage(640, 480, 3);
  cv::Mat base = img.clone();
  cv::rectangle(base, cv::Point(100, 90), cv::Point(420, 330), cv::Scalar(255), 3);
  cv::line(base, cv::Point(450, 50), cv::Point(600, 400), cv::Scalar(0), 3);
  const cv::Mat shift = (cv::Mat_<double>(2, 3) << 1, 0, 6, 0, 1, 4);
  cv::Mat moved;
  cv::warpAffine(base, moved, shift, base.size(), cv::INTER_NEAREST, cv::BORDER_REPLICATE);

  std::vector<RawSegment> a, b;
  cv::Mat da, db;
  lines.extract(base, a, da);
  lines.extract(moved, b, db);
  ASSERT_GE(a.size(), 5u);
  int checked = 0, correct = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    const cv::Point2f expected_mid = 0.5f * (a[i].start + a[i].end) + cv::Point2f(6, 4);
    if (expected_mid.x < 20 || expected_mid.x > 620 || expected_mid.y < 20 || expected_mid.y > 460) continue;
    int best = -1, best_dist = 1 << 30;
    for (size_t j = 0; j < b.size(); ++j) {
      const int d = static_cast<int>(cv::norm(da.row(static_cast<int>(i)), db.row(static_cast<int>(j)), cv::NORM_HAMMING));
      if (d < best_dist) best_dist = d, best = static_cast<int>(j);
    }
    ++checked;
    const cv::Point2f mid = 0.5f * (b[best].start + b[best].end);
    if (cv::norm(mid - expected_mid) < 0.25 * a[i].length) ++correct;
  }
  ASSERT_GE(checked, 5);
  EXPECT_GE(correct, 0.9 * checked);
}
INSTANTIATE_TEST_SUITE_P(LineExtractor, LbdOctave, ::testing::Values(0, 1));

TEST(FeatureExtractor, ProducesUndistortedPointsAndLineCoefficients) {
  const PinholeCamera camera(640, 480, 500.0, 500.0, 319.5, 239.5, RadTanDistortion{-0.1, 0.01, 0.0, 0.0, 0.0});
  FeatureExtractor extractor(FeatureExtractorConfig{}, camera);
  cv::Mat img = testing::texturedImage(640, 480, 11);
  cv::rectangle(img, cv::Point(150, 120), cv::Point(470, 360), cv::Scalar(255), 4);
  cv::Mat bgr;
  cv::cvtColor(img, bgr, cv::COLOR_GRAY2BGR);
  const FeatureFrame f = extractor.extract(ImageFrame{1.5, bgr});
  EXPECT_EQ(f.timestamp, 1.5);
  ASSERT_EQ(f.points.size(), f.keypoints.size());
  EXPECT_GT(f.keypoints.size(), 500u);
  for (size_t i = 0; i < f.points.size(); ++i) {
    const Eigen::Vector2d px(f.keypoints[i].pt.x, f.keypoints[i].pt.y);
    EXPECT_LT((f.points[i] - camera.undistortPoint(px)).norm(), 1e-9);
  }
  ASSERT_FALSE(f.lines.empty());
  EXPECT_EQ(f.line_descriptors.rows, static_cast<int>(f.lines.size()));
  for (const LineSegment& s : f.lines) {
    EXPECT_NEAR(s.coefficients.head<2>().norm(), 1.0, 1e-12);
    EXPECT_NEAR(s.coefficients.dot(s.start.homogeneous()), 0.0, 1e-9);
    EXPECT_NEAR(s.coefficients.dot(s.end.homogeneous()), 0.0, 1e-9);
  }
  EXPECT_EQ(f.pyramid.scale.size(), 8u);
  EXPECT_NEAR(f.pyramid.inv_sigma2[1], 1.0 / (1.2 * 1.2), 1e-12);
}

TEST(FeatureExtractor, RejectsBadImagesAndConfigs) {
  FeatureExtractor extractor(FeatureExtractorConfig{}, vgaCamera());
  EXPECT_THROW(extractor.extract(ImageFrame{0.0, cv::Mat()}), Error);
  EXPECT_THROW(extractor.extract(ImageFrame{0.0, cv::Mat(240, 320, CV_8UC1, cv::Scalar(0))}), Error);
  EXPECT_THROW(extractor.extract(ImageFrame{0.0, cv::Mat(480, 640, CV_32FC1, cv::Scalar(0))}), Error);
  // A blank image is valid input: no features, no crash.
  const FeatureFrame blank = extractor.extract(ImageFrame{0.0, cv::Mat(480, 640, CV_8UC1, cv::Scalar(0))});
  EXPECT_TRUE(blank.keypoints.empty());
  EXPECT_TRUE(blank.lines.empty());
  FeatureExtractorConfig bad;
  bad.orb.scale_factor = 1.0;
  EXPECT_THROW(FeatureExtractor(bad, vgaCamera()), Error);
  bad = {};
  bad.lines.scale = 0.0;
  EXPECT_THROW(FeatureExtractor(bad, vgaCamera()), Error);
  bad = {};
  bad.lines.descriptor_octave = -1;
  EXPECT_THROW(FeatureExtractor(bad, vgaCamera()), Error);
  EXPECT_THROW(FeatureExtractor(FeatureExtractorConfig{}, PinholeCamera()), Error);
}

// ORB and LSD/LBD run side by side under TBB: the frame must not depend on
// whether they did (the deterministic mode limits TBB to one thread).
TEST(FeatureExtractor, SideBySideExtractionEqualsOneThread) {
  cv::Mat img = testing::texturedImage(640, 480, 5);
  cv::rectangle(img, cv::Point(100, 80), cv::Point(500, 400), cv::Scalar(255), 4);
  const ImageFrame frame{2.0, img};
  FeatureExtractor parallel(FeatureExtractorConfig{}, vgaCamera());
  const FeatureFrame a = parallel.extract(frame);
  FeatureFrame b;
  {
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    FeatureExtractor sequential(FeatureExtractorConfig{}, vgaCamera());
    b = sequential.extract(frame);
  }
  ASSERT_GT(a.keypoints.size(), 500u);
  ASSERT_FALSE(a.lines.empty());
  ASSERT_EQ(a.keypoints.size(), b.keypoints.size());
  ASSERT_EQ(a.lines.size(), b.lines.size());
  EXPECT_EQ(cv::norm(a.descriptors, b.descriptors, cv::NORM_HAMMING), 0.0);
  EXPECT_EQ(cv::norm(a.line_descriptors, b.line_descriptors, cv::NORM_HAMMING), 0.0);
  for (size_t i = 0; i < a.lines.size(); ++i) {
    EXPECT_EQ(a.lines[i].start, b.lines[i].start);
    EXPECT_EQ(a.lines[i].end, b.lines[i].end);
  }
}

}  // namespace
}  // namespace lvslam::visual
