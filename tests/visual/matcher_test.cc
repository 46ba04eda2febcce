#include <random>

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "lvslam/visual/feature/feature_extractor.h"
#include "lvslam/visual/match/descriptor_distance.h"
#include "lvslam/visual/match/feature_grid.h"
#include "lvslam/visual/match/line_matcher.h"
#include "lvslam/visual/match/point_matcher.h"
#include "visual/synthetic_images.h"

namespace lvslam::visual {
namespace {

// A textured image with long edges, and the same image rotated by 3 degrees
// and shifted: every feature's true position in the second image is known.
struct ImagePair {
  FeatureFrame a, b;
  cv::Mat warp;  // 2x3, image a -> image b

  Eigen::Vector2d map(const Eigen::Vector2d& p) const {
    return {warp.at<double>(0, 0) * p.x() + warp.at<double>(0, 1) * p.y() + warp.at<double>(0, 2),
            warp.at<double>(1, 0) * p.x() + warp.at<double>(1, 1) * p.y() + warp.at<double>(1, 2)};
  }
};

const ImagePair& imagePair() {
  static const ImagePair pair = [] {
    cv::Mat img = testing::texturedImage(640, 480, 21);
    cv::RNG rng(3);
    for (int i = 0; i < 20; ++i) {
      cv::line(img, cv::Point(rng.uniform(0, 640), rng.uniform(0, 480)),
               cv::Point(rng.uniform(0, 640), rng.uniform(0, 480)), cv::Scalar(rng.uniform(0, 2) * 255), 3);
    }
    ImagePair p;
    p.warp = cv::getRotationMatrix2D(cv::Point2f(320, 240), 3.0, 1.0);
    p.warp.at<double>(0, 2) += 12.0;
    p.warp.at<double>(1, 2) -= 7.0;
    cv::Mat moved;
    cv::warpAffine(img, moved, p.warp, img.size(), cv::INTER_LINEAR, cv::BORDER_REFLECT);
    FeatureExtractor extractor(FeatureExtractorConfig{}, PinholeCamera(640, 480, 450, 450, 319.5, 239.5));
    p.a = extractor.extract(ImageFrame{0.0, img});
    p.b = extractor.extract(ImageFrame{0.1, moved});
    return p;
  }();
  return pair;
}

TEST(DescriptorDistance, MatchesOpenCvHamming) {
  cv::Mat a(2, 32, CV_8U), b(2, 32, CV_8U);
  cv::randu(a, 0, 256);
  cv::randu(b, 0, 256);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(descriptorDistance(a, i, b, i), static_cast<int>(cv::norm(a.row(i), b.row(i), cv::NORM_HAMMING)));
  }
  EXPECT_EQ(descriptorDistance(a, 0, a, 0), 0);
}

TEST(FeatureGrid, RadiusQueryEqualsBruteForce) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> x(-20, 660), y(-20, 500);
  std::vector<Eigen::Vector2d> pts;
  for (int i = 0; i < 500; ++i) pts.emplace_back(x(rng), y(rng));
  const FeatureGrid grid(pts, 640, 480, 32);
  std::vector<int> found;
  for (int q = 0; q < 50; ++q) {
    const Eigen::Vector2d c(x(rng), y(rng));
    const double r = 5.0 + q;
    grid.query(c, r, found);
    std::sort(found.begin(), found.end());
    std::vector<int> expected;
    for (int i = 0; i < 500; ++i) {
      if ((pts[i] - c).norm() <= r) expected.push_back(i);
    }
    EXPECT_EQ(found, expected);
  }
  // Far-away or non-finite queries find nothing and do not overflow.
  grid.query(Eigen::Vector2d(1e300, -1e300), 10.0, found);
  EXPECT_TRUE(found.empty());
  grid.query(Eigen::Vector2d(NAN, 0.0), 10.0, found);
  EXPECT_TRUE(found.empty());
  grid.query(Eigen::Vector2d(100.0, 100.0), INFINITY, found);
  EXPECT_TRUE(found.empty());
}

TEST(PointMatcher, WindowMatchesAreMostlyCorrect) {
  const ImagePair& p = imagePair();
  const FeatureGrid grid(p.b.points, 640, 480);
  const std::vector<PointMatch> matches = matchInWindow(p.a, p.b, grid, 40.0);
  ASSERT_GT(matches.size(), 300u);
  int correct = 0;
  for (const PointMatch& m : matches) {
    if ((p.map(p.a.points[m.index1]) - p.b.points[m.index2]).norm() < 3.0) ++correct;
  }
  EXPECT_GT(correct, 0.95 * matches.size());
}

TEST(PointMatcher, ProjectionMatchesAreMostlyCorrect) {
  const ImagePair& p = imagePair();
  std::vector<ProjectedPoint> projected;
  for (size_t i = 0; i < p.a.points.size(); ++i) {
    projected.push_back({p.map(p.a.points[i]), 6.0, p.a.descriptors.row(static_cast<int>(i))});
  }
  const std::vector<PointMatch> matches = matchByProjection(projected, p.b, FeatureGrid(p.b.points, 640, 480));
  ASSERT_GT(matches.size(), 300u);
  int correct = 0;
  for (const PointMatch& m : matches) {
    if ((projected[m.index1].pixel - p.b.points[m.index2]).norm() < 3.0) ++correct;
  }
  EXPECT_GT(correct, 0.95 * matches.size());
}

bool lineMatchIsCorrect(const ImagePair& p, const LineSegment& s, const LineSegment& t) {
  const Eigen::Vector2d a0 = p.map(s.start), a1 = p.map(s.end);
  return std::abs(t.coefficients.dot((0.5 * (a0 + a1)).homogeneous())) < 3.0 &&
         segmentAngleDeg(a0, a1, t.start, t.end) < 3.0;
}

TEST(LineMatcher, FrameToFrameMatchesAreCorrect) {
  const ImagePair& p = imagePair();
  ASSERT_GE(p.a.lines.size(), 15u);
  const std::vector<LineMatch> matches = matchLines(p.a, p.b);
  ASSERT_GE(matches.size(), 10u);
  int correct = 0;
  for (const LineMatch& m : matches) correct += lineMatchIsCorrect(p, p.a.lines[m.index1], p.b.lines[m.index2]);
  EXPECT_GT(correct, 0.9 * matches.size());
}

TEST(LineMatcher, ProjectionMatchesAreCorrect) {
  const ImagePair& p = imagePair();
  std::vector<ProjectedLine> projected;
  for (size_t i = 0; i < p.a.lines.size(); ++i) {
    projected.push_back({p.map(p.a.lines[i].start), p.map(p.a.lines[i].end), p.a.line_descriptors.row(static_cast<int>(i))});
  }
  const std::vector<LineMatch> matches = matchLinesByProjection(projected, p.b);
  ASSERT_GE(matches.size(), 10u);
  int correct = 0;
  for (const LineMatch& m : matches) correct += lineMatchIsCorrect(p, p.a.lines[m.index1], p.b.lines[m.index2]);
  EXPECT_GT(correct, 0.9 * matches.size());
  // Each frame segment is used at most once.
  std::vector<int> used(p.b.lines.size(), 0);
  for (const LineMatch& m : matches) EXPECT_EQ(++used[m.index2], 1);
}

TEST(LineMatcher, MissingDescriptorsGiveNoMatches) {
  FeatureFrame a = imagePair().a;
  a.line_descriptors.release();
  EXPECT_TRUE(matchLines(a, imagePair().b).empty());
}

}  // namespace
}  // namespace lvslam::visual
