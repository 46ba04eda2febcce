// ORB-SLAM's keyframe rule c2 with frame intervals, case by case.
#include "lvslam/visual/tracking/keyframe_policy.h"

#include <gtest/gtest.h>

namespace lvslam::visual {
namespace {

TEST(KeyframePolicy, AFrameThatStillSeesTheReferenceWaitsForTheLongestInterval) {
  const KeyframePolicy p;  // ratio 0.9, min tracked 100, intervals 3 .. 5
  // 250 of the reference's 260 points: more than 90 %, so no new ground.
  EXPECT_FALSE(keyframeNeeded(p, 250, 260, 3));
  EXPECT_FALSE(keyframeNeeded(p, 250, 260, 4));
  EXPECT_TRUE(keyframeNeeded(p, 250, 260, 5));
  EXPECT_TRUE(keyframeNeeded(p, 250, 260, 9));
}

TEST(KeyframePolicy, NewGroundMakesAKeyframeFromTheShortestInterval) {
  const KeyframePolicy p;
  // 230 of 260 is 88 %: below the 90 % overlap.
  EXPECT_FALSE(keyframeNeeded(p, 230, 260, 2));
  EXPECT_TRUE(keyframeNeeded(p, 230, 260, 3));
  // Fewer than min_tracked points, whatever the reference had.
  EXPECT_FALSE(keyframeNeeded(p, 99, 100, 2));
  EXPECT_TRUE(keyframeNeeded(p, 99, 100, 3));
  EXPECT_FALSE(keyframeNeeded(p, 100, 100, 3));
}

TEST(KeyframePolicy, TooFewInliersNeverMakeAKeyframe) {
  const KeyframePolicy p;
  EXPECT_FALSE(keyframeNeeded(p, 15, 300, 3));
  EXPECT_FALSE(keyframeNeeded(p, 15, 300, 50));
  EXPECT_TRUE(keyframeNeeded(p, 16, 300, 3));
}

TEST(KeyframePolicy, SettingsChangeTheDecision) {
  KeyframePolicy p;
  p.tracked_ratio = 0.8;
  p.min_tracked = 50;
  p.min_interval = 6;
  p.max_interval = 10;
  EXPECT_FALSE(keyframeNeeded(p, 230, 260, 5));  // 88 % now counts as overlap ...
  EXPECT_FALSE(keyframeNeeded(p, 230, 260, 9));
  EXPECT_TRUE(keyframeNeeded(p, 230, 260, 10));  // ... until the longest interval
  EXPECT_FALSE(keyframeNeeded(p, 200, 260, 5));  // 77 %: new ground, but too soon
  EXPECT_TRUE(keyframeNeeded(p, 200, 260, 6));
}

}  // namespace
}  // namespace lvslam::visual
