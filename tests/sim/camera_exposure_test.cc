#include <cmath>

#include <gtest/gtest.h>

#include "lvslam/sim/camera_renderer.h"

namespace lvslam::sim {
namespace {

double meanOf(const cv::Mat& image) { return cv::mean(image)[0]; }

// The lights dim to a quarter: the next frame is far too dark, the exposure
// follows with the first-order lag of auto_exposure.h (alpha = 1 - exp(-1 /
// (15 Hz * 0.5 s)) = 0.125 per frame), not at once, and brings the mean
// brightness back within 20 % of the target in about a second.
TEST(AutoExposure, BringsTheBrightnessBackAfterALightingChangeWithTheLag) {
  SimOptions options;
  options.auto_exposure = true;
  options.duration = 10.0;
  Scenario scenario = makeScenario(options);
  const CameraRenderer renderer(scenario);
  const AutoExposureConfig& config = scenario.camera.auto_exposure;
  const double period = 1.0 / scenario.camera.rate_hz, alpha = 1.0 - std::exp(-period / config.time_constant);
  AutoExposure exposure(config, scenario.camera.exposure, period);
  const auto inRange = [&](double mean) { return std::abs(std::log(mean / config.target)) < std::log(1.2); };
  const auto frame = [&](int k) {
    const double factor = exposure.factor();
    const cv::Mat image = renderer.renderImage(1.0 + k * period, exposure.current());
    exposure.update(image);
    // The response is exactly first order in the log of the exposure.
    EXPECT_NEAR(std::log(exposure.factor()) - std::log(factor),
                alpha * (std::log(config.target) - std::log(meanOf(image))), 1e-12);
    return meanOf(image);
  };
  int k = 0;
  for (; k < 40; ++k) frame(k);  // settle under the day's light
  EXPECT_TRUE(inRange(frame(k++)));
  const double settled = exposure.factor();
  scenario.lighting.ambient *= 0.25;
  scenario.lighting.directional *= 0.25;
  const double dark = frame(k++);
  EXPECT_FALSE(inRange(dark)) << dark;
  EXPECT_LT(dark, 0.4 * config.target);
  for (int i = 0; i < 4; ++i) EXPECT_FALSE(inRange(frame(k++))) << "the lag: frame " << i + 2 << " after the change";
  int frames_back = 0;
  while (!inRange(frame(k++)) && frames_back < 60) ++frames_back;
  EXPECT_GE(frames_back, 8);
  EXPECT_LE(frames_back, 22);  // (1 - alpha)^n log 4 < log 1.2 for n >= 16 under a linear response
  EXPECT_NEAR(exposure.factor() / settled, 4.0, 1.2);
  // Shutter first, up to its limit, then gain.
  EXPECT_DOUBLE_EQ(exposure.current().time,
                   std::min(scenario.camera.exposure * exposure.factor(), config.max_exposure));
}

TEST(AutoExposure, OffKeepsTheBaseExposure) {
  AutoExposure off(AutoExposureConfig{}, 0.012, 1.0 / 15.0);
  off.update(cv::Mat(10, 10, CV_8U, cv::Scalar(5)));
  EXPECT_EQ(off.current().time, 0.012);
  EXPECT_EQ(off.current().gain, 1.0);
}

// Rolling shutter: row y is what a global-shutter camera sees at the row's
// own time t + (y - 239.5) * line_time; the time stamp is the middle row's.
TEST(RollingShutter, EachRowIsExposedAtItsOwnTime) {
  SimOptions options;
  options.scenario = "hall";
  options.rolling_shutter = true;
  options.duration = 20.0;
  const Scenario rolling = makeScenario(options);
  Scenario global = rolling;
  global.camera.line_time = 0.0;
  const double t = 12.0, line = rolling.camera.line_time;
  ASSERT_NEAR(line * rolling.camera.camera.height(), 0.024, 1e-12);
  const CameraRenderer rolling_renderer(rolling), global_renderer(global);
  EXPECT_DOUBLE_EQ(rolling_renderer.rowTime(t, 0), t - 239.5 * line);
  EXPECT_DOUBLE_EQ(rolling_renderer.rowTime(t, 479), t + 239.5 * line);
  const cv::Mat depth = rolling_renderer.renderDepth(t);
  const cv::Mat at_stamp = global_renderer.renderDepth(t);
  for (const int y : {0, 17, 240, 479}) {
    const cv::Mat own = global_renderer.renderDepth(rolling_renderer.rowTime(t, y));
    EXPECT_EQ(cv::norm(depth.row(y), own.row(y), cv::NORM_INF), 0.0) << "row " << y;
  }
  // At about 1 m/s the first and last rows, 24 ms apart, differ from a
  // global shutter at the stamp.
  EXPECT_GT(cv::norm(depth.row(0), at_stamp.row(0), cv::NORM_INF), 1e-3);
  EXPECT_GT(cv::norm(depth.row(479), at_stamp.row(479), cv::NORM_INF), 1e-3);
}

}  // namespace
}  // namespace lvslam::sim
