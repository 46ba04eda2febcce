// Map culling (ORB-SLAM's MapPointCulling and KeyFrameCulling): exactly the
// landmarks and keyframes the documented rules name are removed.
#include "lvslam/visual/module/map_culling.h"

#include <gtest/gtest.h>

namespace lvslam::visual {
namespace {

// A map of `keyframes` keyframes (ids 0..n-1) with 40 keypoints and 4 line
// segments each, and landmarks observed by the keyframes named.
struct CullingMap {
  VisualMap map;
  explicit CullingMap(int keyframes) {
    for (int k = 0; k < keyframes; ++k) {
      Keyframe kf;
      kf.features.keypoints.resize(40);
      kf.features.lines.resize(4);
      map.addKeyframe(std::move(kf));
    }
  }
  // Uses each keyframe's next free keypoint / segment.
  int point(const std::vector<int>& observers) {
    const int id = map.addPointLandmark(Eigen::Vector3d::Zero(), cv::Mat());
    for (const int k : observers) map.addPointObservation(id, k, freeIndex(map.keyframe(k).point_landmark));
    return id;
  }
  int line(const std::vector<int>& observers) {
    const int id = map.addLineLandmark(PluckerLine::fromPoints(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()),
                                       Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), cv::Mat());
    for (const int k : observers) map.addLineObservation(id, k, freeIndex(map.keyframe(k).line_landmark));
    return id;
  }
  static int freeIndex(const std::vector<int>& table) {
    for (std::size_t i = 0; i < table.size(); ++i)
      if (table[i] < 0) return static_cast<int>(i);
    ADD_FAILURE() << "no free feature";
    return -1;
  }
};

TEST(MapCulling, RecentPointsFailingEitherTestAreCulledOthersStayOrAreReleased) {
  CullingMap m(5);
  const CullingConfig config;  // found / visible >= 0.25; >= 2 observers after 2 keyframes; recent for 3
  const int current = 4;
  UsageTable recent;
  const int rarely_found = m.point({3, 4});
  recent[rarely_found] = {4, 9, 2};  // 2 < 0.25 * 9, though just made
  const int found_enough = m.point({4});
  recent[found_enough] = {4, 8, 2};  // 2 = 0.25 * 8; one observer, but on probation only from age 2
  const int lonely = m.point({4});
  recent[lonely] = {2, 3, 3};  // age 2 with one observer
  const int observed = m.point({2, 4});
  recent[observed] = {2, 3, 3};  // age 2 with two observers: kept, still recent
  const int released = m.point({1, 3});
  recent[released] = {1, 3, 3};  // age 3: no longer recent, kept
  const int removed = m.point({4});
  m.map.removePoint(removed);
  recent[removed] = {4, 1, 1};
  recent[12345] = {4, 1, 1};  // not in the map

  EXPECT_EQ(cullRecentPoints(m.map, recent, current, config), 2);
  EXPECT_FALSE(m.map.hasPoint(rarely_found));
  EXPECT_FALSE(m.map.hasPoint(lonely));
  for (const int kept : {found_enough, observed, released}) EXPECT_TRUE(m.map.hasPoint(kept)) << kept;
  EXPECT_EQ(m.map.keyframe(4).point_landmark[0], -1);  // rarely_found's observation went with it
  // Only the two still recent remain in the table.
  EXPECT_EQ(recent.size(), 2u);
  EXPECT_EQ(recent.count(found_enough), 1u);
  EXPECT_EQ(recent.count(observed), 1u);
}

TEST(MapCulling, RecentLinesNeedTwoObserversEvenWhenPointsNeedMore) {
  CullingMap m(5);
  CullingConfig config;
  config.min_observations = 3;
  UsageTable points, lines;
  const int point = m.point({2, 4});
  points[point] = {2, 3, 3};
  const int line = m.line({2, 4});
  lines[line] = {2, 3, 3};
  const int lonely_line = m.line({2});
  lines[lonely_line] = {2, 3, 3};
  const int rare_line = m.line({3, 4});
  lines[rare_line] = {3, 5, 1};
  EXPECT_EQ(cullRecentPoints(m.map, points, 4, config), 1);
  EXPECT_FALSE(m.map.hasPoint(point));
  EXPECT_EQ(cullRecentLines(m.map, lines, 4, config), 2);
  EXPECT_TRUE(m.map.hasLine(line));
  EXPECT_FALSE(m.map.hasLine(lonely_line));
  EXPECT_FALSE(m.map.hasLine(rare_line));
  EXPECT_EQ(lines.size(), 1u);
}

TEST(MapCulling, AKeyframeIsRedundantWhenOverNinetyPercentOfItsLandmarksAreSeenByThreeOthers) {
  CullingMap m(7);
  const CullingConfig config;
  // Keyframe 2: 10 landmarks, each seen by 0, 1, 3 and 4 too: redundant.
  for (int i = 0; i < 8; ++i) m.point({0, 1, 2, 3, 4});
  for (int i = 0; i < 2; ++i) m.line({0, 1, 2, 3, 4});
  // Keyframe 5: 9 of 10 seen by three others (9 = 0.9 * 10: not more than 90 %).
  for (int i = 0; i < 9; ++i) m.point({0, 1, 3, 5});
  m.point({5});
  // Keyframe 6 (the newest) and keyframe 0 (the map's first) are redundant but kept.
  for (int i = 0; i < 6; ++i) m.point({0, 1, 3, 6});
  const std::vector<int> removed = cullRedundantKeyframes(m.map, {0, 2, 5, 6, 99}, 6, config);
  EXPECT_EQ(removed, std::vector<int>{2});
  EXPECT_FALSE(m.map.hasKeyframe(2));
  for (const int k : {0, 1, 3, 4, 5, 6}) EXPECT_TRUE(m.map.hasKeyframe(k)) << k;
  // With keyframe 2 gone its landmarks have three other observers left (0, 1, 3 for keyframe 4).
  EXPECT_EQ(cullRedundantKeyframes(m.map, {4}, 6, config), std::vector<int>{4});
}

TEST(MapCulling, KeyframesRedundantOnlyThroughEachOtherAreNotBothRemoved) {
  CullingMap m(5);
  const CullingConfig config;
  // Landmarks seen by keyframes 1-4: each has three other observers, until one of them goes.
  for (int i = 0; i < 10; ++i) m.point({1, 2, 3, 4});
  EXPECT_EQ(cullRedundantKeyframes(m.map, {2, 3}, 4, config), std::vector<int>{2});
  EXPECT_TRUE(m.map.hasKeyframe(3));
  // A keyframe without landmarks is never redundant.
  CullingMap empty(3);
  EXPECT_TRUE(cullRedundantKeyframes(empty.map, {1}, 2, config).empty());
}

}  // namespace
}  // namespace lvslam::visual
