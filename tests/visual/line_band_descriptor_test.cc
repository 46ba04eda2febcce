#include "lvslam/visual/feature/line_band_descriptor.h"

#include <array>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "lvslam/visual/match/descriptor_distance.h"
#include "visual/synthetic_images.h"

namespace lvslam::visual {
namespace {

using Bits = std::array<uint8_t, LineBandDescriptor::kBytes>;

Bits describe(const cv::Mat& image, cv::Point2f a, cv::Point2f b) {
  LineBandDescriptor lbd;
  lbd.setImage(image);
  Bits out{};
  lbd.describe(a, b, out.data());
  return out;
}

// A textured image with a long bright bar: the edges to describe.
cv::Mat barImage() {
  cv::Mat img = testing::texturedImage(320, 240, 5);
  cv::rectangle(img, cv::Point(60, 100), cv::Point(260, 112), cv::Scalar(255), cv::FILLED);
  return img;
}

// A quarter turn of the image moves every pixel exactly and turns the Sobel
// gradients with it, so the turned segment has the same descriptor.
TEST(LineBandDescriptor, AQuarterTurnKeepsTheDescriptor) {
  const cv::Mat img = barImage();
  cv::Mat turned;
  cv::rotate(img, turned, cv::ROTATE_90_CLOCKWISE);  // (x, y) -> (rows - 1 - y, x)
  const auto turn = [&](cv::Point2f p) { return cv::Point2f(static_cast<float>(img.rows - 1) - p.y, p.x); };
  // Off the half-pixel, so that nearest-pixel sampling rounds alike both ways.
  const cv::Point2f a(70.25f, 99.25f), b(250.25f, 99.25f);
  const Bits original = describe(img, a, b);
  const Bits rotated = describe(turned, turn(a), turn(b));
  EXPECT_LE(hammingDistance256(original.data(), rotated.data()), 4);
  // Another edge of the same image is far from it.
  const Bits other = describe(img, cv::Point2f(70.25f, 112.25f), cv::Point2f(250.25f, 112.25f));
  EXPECT_GT(hammingDistance256(original.data(), other.data()), 40);
}

// Means and deviations are normalised: halving the contrast changes nothing
// but rounding.
TEST(LineBandDescriptor, ContrastDoesNotMatter) {
  const cv::Mat img = barImage();
  cv::Mat faint;
  img.convertTo(faint, CV_8U, 0.5, 40.0);
  const cv::Point2f a(70.0f, 99.5f), b(250.0f, 99.5f);
  EXPECT_LE(hammingDistance256(describe(img, a, b).data(), describe(faint, a, b).data()), 12);
}

TEST(LineBandDescriptor, DegenerateAndOutsideSegmentsAreSafe) {
  const cv::Mat img = barImage();
  const Bits zero{};
  EXPECT_EQ(describe(img, cv::Point2f(10, 10), cv::Point2f(10, 10)), zero);  // no direction: no bits
  EXPECT_EQ(describe(img, cv::Point2f(NAN, 10), cv::Point2f(10, 10)), zero);
  EXPECT_EQ(describe(img, cv::Point2f(-1e9f, 10), cv::Point2f(1e9f, 10)), zero);  // not 2e9 samples
  // Half outside the image: sampled with clamping, still describes the edge.
  const Bits inside = describe(img, cv::Point2f(60.0f, 99.5f), cv::Point2f(259.0f, 99.5f));
  const Bits beyond = describe(img, cv::Point2f(-140.0f, 99.5f), cv::Point2f(259.0f, 99.5f));
  EXPECT_NE(beyond, zero);
  EXPECT_LT(hammingDistance256(inside.data(), beyond.data()), 128);
  LineBandDescriptor no_image;
  Bits out{};
  out.fill(7);
  no_image.describe(cv::Point2f(0, 0), cv::Point2f(5, 5), out.data());
  EXPECT_EQ(out, zero);
}

}  // namespace
}  // namespace lvslam::visual
