#include "lvslam/system/detection_module.h"

#include <gtest/gtest.h>

namespace lvslam::system {
namespace {

VisualHealth healthy(double t) {
  return {t, VisualState::kTracking, 300, 40, 0.9, 120.0, 50.0};
}

const MotionDisagreement kAgree{0.002, 0.05};

TEST(DetectionModule, StartsOnLidarAndTrustsVisionAfterAHealthyStreak) {
  DetectionConfig config;
  config.frames_to_recover = 5;
  DetectionModule d(config);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(d.update(healthy(i), kAgree), OutputSource::kLidar) << i;
  EXPECT_EQ(d.update(healthy(4), kAgree), OutputSource::kVisual);
  ASSERT_EQ(d.switches().size(), 1u);
  EXPECT_EQ(d.switches()[0].t, 4.0);
  EXPECT_EQ(d.switches()[0].to, OutputSource::kVisual);
}

TEST(DetectionModule, BlackoutSwitchesToLidarAtOnceWithTheReason) {
  DetectionConfig config;
  config.frames_to_recover = 3;
  DetectionModule d(config);
  for (int i = 0; i < 3; ++i) d.update(healthy(i), kAgree);
  ASSERT_EQ(d.source(), OutputSource::kVisual);
  VisualHealth black = healthy(3);
  black.brightness = 0.0;
  black.contrast = 0.0;
  black.state = VisualState::kLost;
  EXPECT_EQ(d.update(black, std::nullopt), OutputSource::kLidar);
  ASSERT_EQ(d.switches().size(), 2u);
  EXPECT_EQ(d.switches()[1].t, 3.0);
  EXPECT_NE(d.switches()[1].reason.find("dark"), std::string::npos) << d.switches()[1].reason;
}

TEST(DetectionModule, EachHealthCriterionCountsOnItsOwn) {
  DetectionModule d(DetectionConfig{});
  VisualHealth h = healthy(0);
  h.tracked_points = 10;
  d.update(h, kAgree);
  EXPECT_NE(d.lastProblem().find("tracked points"), std::string::npos);
  h = healthy(1);
  h.inlier_ratio = 0.2;
  d.update(h, kAgree);
  EXPECT_NE(d.lastProblem().find("inlier"), std::string::npos);
  h = healthy(2);
  h.brightness = 252.0;
  d.update(h, kAgree);
  EXPECT_NE(d.lastProblem().find("saturated"), std::string::npos);
  d.update(healthy(3), MotionDisagreement{0.2, 0.0});
  EXPECT_NE(d.lastProblem().find("disagree"), std::string::npos);
  d.update(healthy(4), kAgree);
  EXPECT_EQ(d.lastProblem(), "");
}

TEST(DetectionModule, RecoveryNeedsAgreementWithTheLidar) {
  DetectionConfig config;
  config.frames_to_recover = 2;
  DetectionModule d(config);
  // Healthy-looking frames whose motion is unknown never switch back...
  for (int i = 0; i < 10; ++i) EXPECT_EQ(d.update(healthy(i), std::nullopt), OutputSource::kLidar);
  // ...nor do frames that disagree, and a disagreement resets the streak.
  EXPECT_EQ(d.update(healthy(10), kAgree), OutputSource::kVisual);  // streak of 11 healthy, now known motion
  EXPECT_EQ(d.update(healthy(11), MotionDisagreement{0.5, 3.0}), OutputSource::kLidar);
  EXPECT_EQ(d.update(healthy(12), kAgree), OutputSource::kLidar);
  EXPECT_EQ(d.update(healthy(13), kAgree), OutputSource::kVisual);
  EXPECT_EQ(d.switches().size(), 3u);
}

}  // namespace
}  // namespace lvslam::system
