// The extrinsic check on synthetic frames: straight 3D edges in front of the
// camera seen as image segments (true projection) and as LiDAR line points
// moved by a known extrinsic rotation error, with noise.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "fusion/test_rig.h"
#include "lvslam/core/se3.h"
#include "lvslam/fusion/extrinsic_check.h"

namespace lvslam::fusion::testing {
namespace {

constexpr double kDeg = M_PI / 180.0;

struct SyntheticFrame {
  std::vector<SphereFeature> features;
  std::vector<ImageSegment> segments;
};

// `edges` random 3D segments 2-8 m away; each one inside the image gives its
// segment and LiDAR points every 10 cm with `noise_m` of noise, all turned by
// R_error (what a wrong extrinsic rotation does to the projected features).
SyntheticFrame syntheticFrame(std::mt19937& rng, const Eigen::Matrix3d& R_error, int edges, double noise_m) {
  const PinholeCamera camera = testCamera();
  std::uniform_real_distribution<double> u(-1.0, 1.0), depth(2.0, 8.0), length(1.0, 2.5);
  std::normal_distribution<double> noise(0.0, noise_m);
  SyntheticFrame frame;
  while (static_cast<int>(frame.segments.size()) < edges) {
    const double z = depth(rng);
    const Eigen::Vector3d centre(u(rng) * 0.6 * z, u(rng) * 0.45 * z, z);
    const Eigen::Vector3d d = Eigen::Vector3d(u(rng), u(rng), 0.3 * u(rng)).normalized();
    const double half = 0.5 * length(rng);
    const Eigen::Vector3d a = centre - half * d, b = centre + half * d;
    const auto pa = camera.project(a), pb = camera.project(b);
    if (!pa || !pb || !camera.inImage(*pa) || !camera.inImage(*pb) || (*pb - *pa).norm() < 40.0) continue;
    frame.segments.push_back({*pa, *pb});
    for (double s = 0.0; s <= 2.0 * half; s += 0.1) {
      SphereFeature f;
      f.p_camera = R_error * (a + s * d + Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
      f.direction_camera = R_error * d;
      f.shape = FeatureShape::kLinear;
      frame.features.push_back(f);
    }
  }
  return frame;
}

// Feeds `windows` windows of frames, one frame per block of scans (after the
// first block, skipped while the accumulation fills); returns every verdict.
std::vector<ExtrinsicVerdict> runWindows(const Eigen::Matrix3d& R_error, std::uint32_t seed, int windows,
                                         double noise_m = 0.02) {
  std::mt19937 rng(seed);
  FusionConfig config;
  ExtrinsicCheck check(testCamera(), config);
  std::vector<ExtrinsicVerdict> verdicts;
  const int frames = windows * ExtrinsicCheck::kBlocksPerWindow;
  for (int k = 0; k < frames; ++k) {
    const SyntheticFrame frame = syntheticFrame(rng, R_error, 25, noise_m);
    const std::size_t serial = static_cast<std::size_t>((k + 1) * config.accumulated_scans);
    if (auto v = check.addFrame(serial, 0.5 * k, frame.features, frame.segments)) verdicts.push_back(*v);
  }
  if (auto v = check.finish()) verdicts.push_back(*v);
  return verdicts;
}

TEST(ExtrinsicCheck, FourDegreesOfRotationErrorAreFoundAndMeasured) {
  for (const std::uint32_t seed : {1u, 2u, 3u}) {
    const Eigen::Vector3d axis = Eigen::Vector3d(0.3, -0.8, 0.5).normalized();
    const Eigen::Matrix3d R_error = expSO3(4.0 * kDeg * axis);
    const std::vector<ExtrinsicVerdict> verdicts = runWindows(R_error, seed, ExtrinsicCheck::kMinWindows);
    ASSERT_EQ(verdicts.size(), static_cast<std::size_t>(ExtrinsicCheck::kMinWindows));
    // Too few windows for a verdict until the last.
    for (std::size_t i = 0; i + 1 < verdicts.size(); ++i) EXPECT_FALSE(verdicts[i].misaligned);
    const ExtrinsicVerdict& last = verdicts.back();
    EXPECT_TRUE(last.misaligned) << "seed " << seed;
    EXPECT_EQ(last.windows, ExtrinsicCheck::kMinWindows);
    // The fit undoes the error: its rotation is the error's inverse.
    EXPECT_NEAR(last.misalignment_deg, 4.0, 0.2) << "seed " << seed;
    EXPECT_LT(logSO3(expSO3(last.rotation) * R_error).norm(), 0.2 * kDeg);
  }
}

TEST(ExtrinsicCheck, ACorrectExtrinsicIsNotCalledMisaligned) {
  for (const std::uint32_t seed : {1u, 2u, 3u, 4u, 5u}) {
    const std::vector<ExtrinsicVerdict> verdicts = runWindows(Eigen::Matrix3d::Identity(), seed, 6);
    ASSERT_EQ(verdicts.size(), 6u);
    for (const ExtrinsicVerdict& v : verdicts) EXPECT_FALSE(v.misaligned) << "seed " << seed;
    EXPECT_LT(verdicts.back().misalignment_deg, 0.3);
  }
}

TEST(ExtrinsicCheck, ASmallErrorWithinTheToleranceIsNotCalledMisaligned) {
  const Eigen::Matrix3d R_error = expSO3(0.5 * kDeg * Eigen::Vector3d::UnitY());
  const std::vector<ExtrinsicVerdict> verdicts = runWindows(R_error, 7, 6);
  ASSERT_FALSE(verdicts.empty());
  EXPECT_NEAR(verdicts.back().misalignment_deg, 0.5, 0.2);
  EXPECT_FALSE(verdicts.back().misaligned);
}

// Windows that disagree by degrees (what wrong associations do) are no
// evidence, however consistent each one is with itself.
TEST(ExtrinsicCheck, WindowsThatDisagreeAreNotCalledMisaligned) {
  FusionConfig config;
  ExtrinsicCheck check(testCamera(), config);
  std::mt19937 rng(11);
  std::optional<ExtrinsicVerdict> last;
  const Eigen::Vector3d errors_deg[] = {{0, 0, 4}, {0, 0, -3}, {0, 0, 5}, {0, 0, -4}, {0, 0, 4}, {0, 0, -3}};
  std::size_t serial = config.accumulated_scans;
  for (const Eigen::Vector3d& e : errors_deg)
    for (int k = 0; k < ExtrinsicCheck::kBlocksPerWindow; ++k, serial += config.accumulated_scans) {
      const SyntheticFrame frame = syntheticFrame(rng, expSO3(e * kDeg), 25, 0.02);
      if (auto v = check.addFrame(serial, 0.1 * serial, frame.features, frame.segments)) last = v;
    }
  if (auto v = check.finish()) last = v;
  ASSERT_TRUE(last);
  EXPECT_EQ(last->windows, 6);
  EXPECT_FALSE(last->misaligned) << last->misalignment_deg << " +- " << last->sigma_deg;
}

TEST(ExtrinsicCheck, TheTestLooksAtTheLastWindowsOnly) {
  const std::vector<ExtrinsicVerdict> verdicts =
      runWindows(Eigen::Matrix3d::Identity(), 9, ExtrinsicCheck::kMaxWindows + 3, 0.0);
  ASSERT_EQ(verdicts.size(), static_cast<std::size_t>(ExtrinsicCheck::kMaxWindows + 3));
  EXPECT_EQ(verdicts.back().windows, ExtrinsicCheck::kMaxWindows);
}

TEST(ExtrinsicCheck, TheFirstBlockIsSkippedWhileTheAccumulationFills) {
  FusionConfig config;
  ExtrinsicCheck check(testCamera(), config);
  std::mt19937 rng(3);
  const SyntheticFrame frame = syntheticFrame(rng, Eigen::Matrix3d::Identity(), 10, 0.0);
  for (std::size_t serial = 0; serial < static_cast<std::size_t>(config.accumulated_scans); ++serial)
    EXPECT_FALSE(check.addFrame(serial, 0.0, frame.features, frame.segments));
  EXPECT_FALSE(check.finish());
}

TEST(ExtrinsicCheck, NoEdgesOrBadNumbersGiveNoEstimateAndNoCrash) {
  ExtrinsicCheck check(testCamera(), FusionConfig{});
  SphereFeature nan_feature;
  nan_feature.p_camera = Eigen::Vector3d(std::nan(""), 0.0, 1.0);
  nan_feature.shape = FeatureShape::kLinear;
  const std::vector<ImageSegment> degenerate{{Eigen::Vector2d(10, 10), Eigen::Vector2d(10, 10)},
                                             {Eigen::Vector2d(std::nan(""), 0), Eigen::Vector2d(100, 100)}};
  for (std::size_t k = 1; k < 100; ++k) {
    if (auto v = check.addFrame(k * 5, 0.1 * k, {nan_feature}, degenerate)) {
      EXPECT_EQ(v->windows, 0);
    }
    if (auto v = check.addFrame(k * 5 + 1, 0.1 * k, {}, {})) {
      EXPECT_EQ(v->windows, 0);
    }
  }
  EXPECT_FALSE(check.fitRotation({}));
}

TEST(ExtrinsicCheck, StudentQuantilesMatchTheTables) {
  EXPECT_NEAR(studentT999(3), 10.215, 1e-3);
  EXPECT_NEAR(studentT999(30), 3.385, 1e-3);
  EXPECT_NEAR(studentT999(40), 3.307, 0.01);  // expansion beyond the table
  EXPECT_NEAR(studentT999(120), 3.160, 0.01);
}

TEST(ExtrinsicCheck, TheWarningNamesTheFileKeyAndTheEstimate) {
  ExtrinsicVerdict v;
  v.misalignment_deg = 4.04;
  v.sigma_deg = 0.12;
  v.windows = 5;
  const std::string line = extrinsicWarning(v, "seq/sequence.yaml: key 'extrinsics.T_camera_lidar'");
  EXPECT_NE(line.find("seq/sequence.yaml: key 'extrinsics.T_camera_lidar'"), std::string::npos) << line;
  EXPECT_NE(line.find("4.0 deg"), std::string::npos) << line;
  EXPECT_EQ(line.find('\n'), std::string::npos);
}

}  // namespace
}  // namespace lvslam::fusion::testing
