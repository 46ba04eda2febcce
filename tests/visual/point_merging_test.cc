// Landmark fusion between keyframes (ORB-SLAM's SearchInNeighbors / Fuse) on
// exact synthetic observations, and VisualMap::replacePoint.
#include "lvslam/visual/module/point_merging.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <opencv2/core.hpp>

#include "lvslam/core/error.h"
#include "lvslam/visual/tracking/local_keyframes.h"
#include "visual/synthetic_keyframes.h"

namespace lvslam::visual {
namespace {

class PointMergingTest : public ::testing::Test {
 protected:
  void SetUp() override {
    scene_ = testing::makeScene(3, 150, 0, 0.3, 7);
    descriptors_ = testing::randomDescriptors(150);
    for (int c = 0; c < 3; ++c)
      ids_.push_back(map_.addKeyframe(testing::observePoints(scene_, scene_.T_camera_world[c], descriptors_, keypoint_point_[c])));
  }

  // Landmark for scene point i observed by keyframes `cameras` (at its true position + offset).
  int landmark(int i, const std::vector<int>& cameras, const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
    const int id = map_.addPointLandmark(scene_.points[i] + offset, descriptors_.row(i));
    for (const int c : cameras) {
      const int keypoint = testing::keypointOf(keypoint_point_[c], i);
      if (keypoint >= 0) map_.addPointObservation(id, ids_[c], keypoint);
    }
    return id;
  }

  testing::SyntheticScene scene_;
  cv::Mat descriptors_;
  VisualMap map_;
  std::vector<int> ids_;
  std::vector<int> keypoint_point_[3];
};

TEST_F(PointMergingTest, ReplacePointMovesObservationsAndRemovesTheDuplicate) {
  const int a = landmark(0, {0, 1});
  const int b = landmark(0, {2});
  map_.replacePoint(b, a);
  EXPECT_FALSE(map_.hasPoint(b));
  EXPECT_THROW(map_.point(b), Error);
  EXPECT_EQ(map_.point(a).observations.size(), 3u);
  EXPECT_EQ(map_.covisibility().weight(ids_[0], ids_[2]), 1);
  EXPECT_THROW(map_.replacePoint(a, 12345), Error);
}

TEST_F(PointMergingTest, UnobservedProjectionsGainObservationsAndDuplicatesMerge) {
  // Points seen by keyframes 0 and 1 only; keyframe 2 sees the same scene points.
  std::vector<int> shared;
  for (int i = 0; i < 150; ++i) {
    const bool in_all = std::count(keypoint_point_[0].begin(), keypoint_point_[0].end(), i) &&
                        std::count(keypoint_point_[2].begin(), keypoint_point_[2].end(), i);
    if (in_all) shared.push_back(i);
  }
  ASSERT_GT(shared.size(), 40u);
  std::vector<int> old_ids, duplicate_ids;
  for (size_t k = 0; k < shared.size(); ++k) {
    old_ids.push_back(landmark(shared[k], {0, 1}));
    // Every other point also has a duplicate that keyframe 2 created alone, 1 cm off.
    if (k % 2 == 0) duplicate_ids.push_back(landmark(shared[k], {2}, Eigen::Vector3d(0.01, 0.0, 0.0)));
  }
  // A landmark whose descriptor is seen nowhere near its projection must not be fused.
  const int wrong = map_.addPointLandmark(scene_.points[shared[0]] + Eigen::Vector3d(0.5, 0.3, 0.0),
                                          descriptors_.row(shared[1]));
  std::vector<int> candidates = old_ids;
  candidates.push_back(wrong);
  const PointMergingResult r = fusePointsIntoKeyframe(map_, ids_[2], candidates, scene_.K);
  EXPECT_EQ(r.merged, static_cast<int>(duplicate_ids.size()));
  EXPECT_EQ(r.added, static_cast<int>(shared.size() - duplicate_ids.size()));
  for (const int id : old_ids) {
    EXPECT_TRUE(map_.hasPoint(id));
    EXPECT_EQ(map_.point(id).observations.size(), 3u);  // the better observed landmark survives
  }
  for (const int id : duplicate_ids) EXPECT_FALSE(map_.hasPoint(id));
  EXPECT_TRUE(map_.point(wrong).observations.empty());
}

TEST_F(PointMergingTest, LocalKeyframesFollowTheLandmarksTheLastFrameTracked) {
  std::vector<int> seen_by_1_and_2;
  for (const int i : keypoint_point_[2]) {
    if (seen_by_1_and_2.size() < 20 && std::count(keypoint_point_[1].begin(), keypoint_point_[1].end(), i))
      seen_by_1_and_2.push_back(landmark(i, {1, 2}));
  }
  ASSERT_EQ(seen_by_1_and_2.size(), 20u);
  const int only_0 = landmark(keypoint_point_[0][0], {0});
  const LocalKeyframes local = selectLocalKeyframes(map_, seen_by_1_and_2, ids_[0]);
  ASSERT_EQ(local.keyframes.size(), 3u);  // the reference, then the two voted keyframes
  EXPECT_EQ(local.keyframes[0], ids_[0]);
  EXPECT_EQ(local.most_shared, ids_[1]);  // ties: the smaller id first
  map_.removePoint(only_0);
  const LocalKeyframes none = selectLocalKeyframes(map_, {only_0, 999}, ids_[2]);  // removed and unknown ids are ignored
  EXPECT_EQ(none.keyframes, std::vector<int>{ids_[2]});
  EXPECT_EQ(none.most_shared, -1);
}

}  // namespace
}  // namespace lvslam::visual
