// The local mapper on a tiny exact map: three keyframes of a synthetic
// scene, half of the points already landmarks, the other half to be made.
#include "lvslam/visual/module/local_mapper.h"

#include <gtest/gtest.h>

#include "visual/synthetic_keyframes.h"

namespace lvslam::visual {
namespace {

class LocalMapperTest : public ::testing::Test {
 protected:
  void SetUp() override {
    scene_ = testing::makeScene(4, 200, 0, 0.3, 21);
    descriptors_ = testing::randomDescriptors(200);
    for (int c = 0; c < 3; ++c) addKeyframe(c);
    // Landmarks of the even points that keyframes 0 and 1 see, observed by
    // every keyframe that sees them (what tracking found).
    for (int i = 0; i < 200; i += 2)
      if (sees(0, i) && sees(1, i)) landmark(i);
  }

  int addKeyframe(int c) {
    const int id = map_.addKeyframe(
        testing::observePoints(scene_, scene_.T_camera_world[c], descriptors_, point_of_[c]));
    EXPECT_EQ(id, c);
    return id;
  }
  bool sees(int c, int point) const { return keypointOf(c, point) >= 0; }
  int keypointOf(int c, int point) const { return testing::keypointOf(point_of_[c], point); }
  int landmark(int point) {
    const int id = map_.addPointLandmark(scene_.points[point], descriptors_.row(point));
    for (int c = 0; c < static_cast<int>(map_.keyframes().size()); ++c)
      if (sees(c, point)) map_.addPointObservation(id, c, keypointOf(c, point));
    return id;
  }
  // The scene point a landmark stands for (by its first observation).
  int pointOf(int landmark) const {
    const Observation& o = map_.point(landmark).observations.front();
    return point_of_[o.keyframe][o.index];
  }
  std::vector<int> newLandmarks(int first_id) const {
    std::vector<int> ids;
    for (const auto& [id, l] : map_.points())
      if (id >= first_id) ids.push_back(id);
    return ids;
  }

  testing::SyntheticScene scene_;
  cv::Mat descriptors_;
  VisualMap map_;
  std::vector<int> point_of_[4];
};

TEST_F(LocalMapperTest, ANewKeyframeTriangulatesItsUnmappedPointsExactlyAndKeepsTheMap) {
  const int first_new = static_cast<int>(map_.points().size());
  int expected_new = 0, seen_by_all = 0;
  for (int i = 1; i < 200; i += 2) {
    if (!sees(2, i) || !(sees(0, i) || sees(1, i))) continue;
    ++expected_new;
    if (sees(0, i) && sees(1, i)) ++seen_by_all;
  }
  ASSERT_GT(expected_new, 40);
  ASSERT_GT(seen_by_all, 20);
  LocalMapper mapper({}, scene_.K);
  const LocalMappingResult r = mapper.process(map_, 2);
  EXPECT_EQ(r.new_points, expected_new);
  // A point made with one neighbour is found in the other one by projection.
  EXPECT_EQ(r.added_observations, seen_by_all);
  EXPECT_EQ(r.merged_points, 0);
  EXPECT_EQ(r.new_lines, 0);
  EXPECT_TRUE(r.ba_usable);
  EXPECT_EQ(r.culled_points, 0);  // just made, found whenever visible
  EXPECT_TRUE(r.removed_keyframes.empty());  // no landmark has three other observers
  const std::vector<int> made = newLandmarks(first_new);
  ASSERT_EQ(static_cast<int>(made.size()), expected_new);
  for (const int id : made) {
    const int point = pointOf(id);
    EXPECT_EQ(point % 2, 1);
    std::size_t observers = 0;
    for (int c = 0; c < 3; ++c) observers += sees(c, point) ? 1 : 0;
    EXPECT_EQ(map_.point(id).observations.size(), observers) << "point " << point;
  }
  // Exact observations: local BA leaves every pose and point where it was.
  for (int c = 0; c < 3; ++c) {
    EXPECT_LT((map_.keyframe(c).T_camera_world.matrix() - scene_.T_camera_world[c].matrix()).norm(), 1e-6) << c;
  }
  for (const auto& [id, l] : map_.points()) EXPECT_LT((l.p_world - scene_.points[pointOf(id)]).norm(), 1e-6) << id;
}

TEST_F(LocalMapperTest, RecentPointsTrackingRarelyFindsAreCulledAtTheNextKeyframe) {
  LocalMapperConfig config;
  config.cull_keyframes = false;
  LocalMapper mapper(config, scene_.K);
  const int first_new = static_cast<int>(map_.points().size());
  mapper.process(map_, 2);
  const std::vector<int> made = newLandmarks(first_new);
  ASSERT_GT(made.size(), 40u);
  // Four tracked frames see every new point; half of them are found each time.
  std::vector<int> found;
  for (std::size_t j = 0; j < made.size(); j += 2) found.push_back(made[j]);
  for (int frame = 0; frame < 4; ++frame) mapper.countTracking(made, found, {}, {});
  // The next keyframe, with what tracking found in it.
  addKeyframe(3);
  for (const int id : found) {
    const int point = pointOf(id);
    if (sees(3, point)) map_.addPointObservation(id, 3, keypointOf(3, point));
  }
  const LocalMappingResult r = mapper.process(map_, 3);
  // Found 1 of 5 times: 1 < 0.25 * 5. Found 5 of 5 times: kept.
  EXPECT_EQ(r.culled_points, static_cast<int>(made.size() - found.size()));
  for (std::size_t j = 0; j < made.size(); ++j) EXPECT_EQ(map_.hasPoint(made[j]), j % 2 == 0) << made[j];
}

}  // namespace
}  // namespace lvslam::visual
