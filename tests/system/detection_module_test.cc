#include "lvslam/system/detection/detection_module.h"

#include <gtest/gtest.h>

namespace lvslam::system {
namespace {

VisualHealth healthy(double t) {
  return {t, VisualState::kTracking, 300, 40, 0.9, 120.0, 50.0};
}

VisualHealth initializing(double t) {
  VisualHealth h = healthy(t);
  h.state = VisualState::kInitializing;
  h.tracked_points = 0;
  h.tracked_lines = 0;
  h.inlier_ratio = 0.0;
  return h;
}

// Waiting for the first map is not a failure: its first healthy frame is
// admitted at once.
TEST(DetectionModule, StartsOnLidarAndAdmitsTheFirstMapAtItsFirstHealthyFrame) {
  DetectionConfig config;
  config.frames_to_recover = 5;
  DetectionModule d(config);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(d.update(initializing(i)), OutputSource::kLidar) << i;
  EXPECT_NE(d.lastProblem().find("initializing"), std::string::npos);
  EXPECT_EQ(d.update(healthy(3)), OutputSource::kVisual);
  ASSERT_EQ(d.switches().size(), 1u);
  EXPECT_EQ(d.switches()[0].t, 3.0);
  EXPECT_EQ(d.switches()[0].to, OutputSource::kVisual);
}

// A failure before the first admission (here a dark start) asks for the
// streak like any other.
TEST(DetectionModule, AFailureBeforeTheFirstAdmissionNeedsAHealthyStreak) {
  DetectionConfig config;
  config.frames_to_recover = 5;
  DetectionModule d(config);
  VisualHealth dark = initializing(0);
  dark.brightness = 3.0;
  EXPECT_EQ(d.update(dark), OutputSource::kLidar);
  EXPECT_EQ(d.update(initializing(1)), OutputSource::kLidar);
  for (int i = 2; i < 6; ++i) EXPECT_EQ(d.update(healthy(i)), OutputSource::kLidar) << i;
  EXPECT_EQ(d.update(healthy(6)), OutputSource::kVisual);
  ASSERT_EQ(d.switches().size(), 1u);
  EXPECT_EQ(d.switches()[0].t, 6.0);
}

TEST(DetectionModule, BlackoutSwitchesToLidarAtOnceWithTheReason) {
  DetectionConfig config;
  config.frames_to_recover = 3;
  DetectionModule d(config);
  for (int i = 0; i < 3; ++i) d.update(healthy(i));
  ASSERT_EQ(d.source(), OutputSource::kVisual);
  VisualHealth black = healthy(3);
  black.brightness = 0.0;
  black.contrast = 0.0;
  black.state = VisualState::kLost;
  EXPECT_EQ(d.update(black), OutputSource::kLidar);
  ASSERT_EQ(d.switches().size(), 2u);
  EXPECT_EQ(d.switches()[1].t, 3.0);
  EXPECT_NE(d.switches()[1].reason.find("dark"), std::string::npos) << d.switches()[1].reason;
}

TEST(DetectionModule, EachHealthCriterionCountsOnItsOwn) {
  DetectionModule d(DetectionConfig{});
  VisualHealth h = healthy(0);
  h.tracked_points = 10;
  d.update(h);
  EXPECT_NE(d.lastProblem().find("tracked points"), std::string::npos);
  h = healthy(1);
  h.inlier_ratio = 0.2;
  d.update(h);
  EXPECT_NE(d.lastProblem().find("inlier"), std::string::npos);
  h = healthy(2);
  h.brightness = 252.0;
  d.update(h);
  EXPECT_NE(d.lastProblem().find("saturated"), std::string::npos);
  d.update(healthy(4));
  EXPECT_EQ(d.lastProblem(), "");
}

// Vision is judged by its own health only: an unhealthy frame resets the
// streak, and nothing about the LiDAR enters.
TEST(DetectionModule, RecoveryNeedsAHealthyStreakAgain) {
  DetectionConfig config;
  config.frames_to_recover = 3;
  DetectionModule d(config);
  for (int i = 0; i < 3; ++i) d.update(healthy(i));
  ASSERT_EQ(d.source(), OutputSource::kVisual);
  VisualHealth weak = healthy(3);
  weak.tracked_points = 5;
  EXPECT_EQ(d.update(weak), OutputSource::kLidar);
  EXPECT_EQ(d.update(healthy(4)), OutputSource::kLidar);
  EXPECT_EQ(d.update(healthy(5)), OutputSource::kLidar);
  EXPECT_EQ(d.update(healthy(6)), OutputSource::kVisual);
  EXPECT_EQ(d.switches().size(), 3u);
}

}  // namespace
}  // namespace lvslam::system
