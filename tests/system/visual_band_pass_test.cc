// The visual band-pass of the fused output (visual_band_pass.h) against
// values worked out by hand.
#include <cmath>
#include <functional>

#include <gtest/gtest.h>

#include "lvslam/system/visual_band_pass.h"

namespace lvslam::system {
namespace {

constexpr double kDt = 1.0 / 15.0;  // the simulated camera's rate

std::vector<VisualDifference> run(int frames, const std::function<Eigen::Vector3d(int)>& d, int map_id = 0) {
  std::vector<VisualDifference> out;
  for (int j = 0; j < frames; ++j) out.push_back({j * kDt, map_id, d(j)});
  return out;
}

TEST(VisualBandPass, AConstantOffsetPassesNothing) {
  const Eigen::Vector3d offset(0.02, -0.01, 0.005);
  const auto c = visualBandPass(run(30, [&](int) { return offset; }), {});
  for (int j = 0; j < 30; ++j) EXPECT_LT(c[j].norm(), 1e-15) << j;
}

// Centred Gaussians: a bump symmetric about frame 20 gives a correction
// symmetric about it (a causal filter would lag it), largest at the bump.
TEST(VisualBandPass, ZeroPhase) {
  const auto bump = [](int j) { return Eigen::Vector3d(0, 0, 0.01 * std::exp(-0.5 * std::pow((j - 20) / 2.0, 2))); };
  const auto c = visualBandPass(run(41, bump), {});
  for (int k = 1; k <= 12; ++k) EXPECT_NEAR(c[20 - k].z(), c[20 + k].z(), 1e-15) << k;
  for (int j = 0; j < 41; ++j) EXPECT_LE(c[j].z(), c[20].z()) << j;
  EXPECT_GT(c[20].z(), 0.0);
}

// Away from the run's ends a slow sine passes the wide Gaussian's complement:
// gain * (1 - exp(-(2 pi f sigma)^2 / 2)), the continuous Gaussian's
// response, which the 15 Hz samples of a 0.32 s Gaussian follow closely.
TEST(VisualBandPass, ASlowSinePassesTheComplementOfTheWideGaussian) {
  const VisualBandPassConfig config{.gain = 0.5, .gain_vertical = 0.5, .sigma_s = 0.32, .sigma_fast_s = 0.0};
  const double f = 0.2, a = 0.01;
  const auto sine = [&](int j) { return Eigen::Vector3d(a * std::sin(2 * M_PI * f * j * kDt), 0, 0); };
  const auto c = visualBandPass(run(300, sine), config);
  const double response = 1.0 - std::exp(-0.5 * std::pow(2 * M_PI * f * 0.32, 2));  // 0.078
  for (int j = 100; j < 200; ++j) EXPECT_NEAR(c[j].x(), 0.5 * response * sine(j).x(), 0.003 * a) << j;
}

// Noise that alternates every frame (7.5 Hz): the wide Gaussian's mean of it
// is about 0, the narrow one (sigma 0.04 s, frames within 0.12 s: the
// neighbours, weight w = exp(-0.5 (dt / 0.04)^2) = 0.249) keeps
// (1 - 2 w) / (1 + 2 w) = 0.334 of it, where a high-pass keeps all.
TEST(VisualBandPass, TheNarrowGaussianTakesOutFrameNoise) {
  const auto alternating = [](int j) { return Eigen::Vector3d(0, 0, j % 2 == 0 ? 0.002 : -0.002); };
  const double w = std::exp(-0.5 * std::pow(kDt / 0.04, 2));
  const double kept = (1 - 2 * w) / (1 + 2 * w);
  VisualBandPassConfig config{.gain = 1.0, .gain_vertical = 1.0, .sigma_s = 0.32, .sigma_fast_s = 0.04};
  const auto band = visualBandPass(run(60, alternating), config);
  config.sigma_fast_s = 0.0;
  const auto high = visualBandPass(run(60, alternating), config);
  for (int j = 20; j < 40; ++j) {
    EXPECT_NEAR(band[j].z(), kept * alternating(j).z(), 2e-5) << j;
    EXPECT_NEAR(high[j].z(), alternating(j).z(), 2e-5) << j;
  }
}

// Each run of trusted frames of one map is filtered alone: two constant
// runs, separated by a new map or by a frame without vision, pass nothing
// (filtered as one, the step between them would pass).
TEST(VisualBandPass, AGapOrANewMapStartsAnew) {
  const auto step = [](int j) { return Eigen::Vector3d(j < 10 ? 0.0 : 0.05, 0, 0); };
  std::vector<VisualDifference> frames = run(20, step);
  EXPECT_GT(visualBandPass(frames, {})[9].norm(), 1e-4);  // one run: the step passes
  for (int j = 10; j < 20; ++j) frames[j].map_id = 1;     // a new map at the step
  for (const Eigen::Vector3d& c : visualBandPass(frames, {})) EXPECT_LT(c.norm(), 1e-15);
  frames = run(20, step);
  frames[10].d.reset();  // vision out for one frame at the step
  for (const Eigen::Vector3d& c : visualBandPass(frames, {})) EXPECT_LT(c.norm(), 1e-15);
}

TEST(VisualBandPass, GainZeroIsOff) {
  const auto c = visualBandPass(run(10, [](int j) { return Eigen::Vector3d(j * 0.01, -j * 0.02, j * 0.03); }),
                                {.gain = 0.0, .gain_vertical = 0.0});
  for (const Eigen::Vector3d& x : c) EXPECT_EQ(x, Eigen::Vector3d::Zero());
}

// The odometry frame's z takes its own share of the same band-passed value.
TEST(VisualBandPass, TheVerticalTakesItsOwnShare) {
  const auto c = visualBandPass(run(12, [](int j) { return Eigen::Vector3d::Constant(0.01 * j * j); }),
                                {.gain = 0.4, .gain_vertical = 0.8});
  ASSERT_GT(c[11].norm(), 1e-4);
  for (const Eigen::Vector3d& x : c) {
    EXPECT_NEAR(x.y(), x.x(), 1e-15);
    EXPECT_NEAR(x.z(), 2.0 * x.x(), 1e-15);
  }
}

}  // namespace
}  // namespace lvslam::system
