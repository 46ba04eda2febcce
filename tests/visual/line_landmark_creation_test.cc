#include "lvslam/visual/module/line_landmark_creation.h"

#include <gtest/gtest.h>

#include "visual/synthetic_scene.h"

namespace lvslam::visual {
namespace {

TEST(LineLandmarkCreation, TriangulatesMatchedSegmentsIntoTheMap) {
  const testing::SyntheticScene s = testing::makeScene(2, 0, 25, 0.4, 31);
  VisualMap map;
  std::vector<int> kf_ids;
  std::vector<std::vector<int>> segment_of_line(2);  // per keyframe: scene segment of each feature line
  for (int k = 0; k < 2; ++k) {
    Keyframe kf;
    kf.T_camera_world = s.T_camera_world[k];
    for (size_t j = 0; j < s.segments.size(); ++j) {
      // Each view sees a different part of the segment.
      const auto& seg = s.segments[j];
      const Eigen::Vector3d a = s.project(kf.T_camera_world, seg.a + (0.05 + 0.1 * k) * (seg.b - seg.a));
      const Eigen::Vector3d b = s.project(kf.T_camera_world, seg.a + (0.9 - 0.1 * k) * (seg.b - seg.a));
      if (!s.visible(a) || !s.visible(b)) continue;
      LineSegment ls;
      ls.start = a.head<2>();
      ls.end = b.head<2>();
      kf.features.lines.push_back(ls);
      segment_of_line[k].push_back(static_cast<int>(j));
    }
    kf_ids.push_back(map.addKeyframe(std::move(kf)));
  }
  std::vector<LineMatch> matches;
  for (size_t i = 0; i < segment_of_line[0].size(); ++i) {
    for (size_t j = 0; j < segment_of_line[1].size(); ++j) {
      if (segment_of_line[0][i] == segment_of_line[1][j]) matches.push_back({static_cast<int>(i), static_cast<int>(j), 0});
    }
  }
  ASSERT_GE(matches.size(), 15u);
  const std::vector<int> created = createLineLandmarks(map, kf_ids[0], kf_ids[1], matches, s.K);
  EXPECT_GE(created.size(), 0.6 * matches.size());
  // Exactly the well-posed lines were created: those whose planes through the
  // two camera centres meet at a clear angle (degenerate ones lie close to an
  // epipolar plane).
  const Eigen::Vector3d c1 = s.T_camera_world[0].inverse().translation(), c2 = s.T_camera_world[1].inverse().translation();
  for (const LineMatch& m : matches) {
    const auto& seg = s.segments[segment_of_line[0][m.index1]];
    const Eigen::Vector3d n1 = (seg.a - c1).cross(seg.b - c1).normalized(), n2 = (seg.a - c2).cross(seg.b - c2).normalized();
    const double angle_deg = std::asin(std::min(1.0, n1.cross(n2).norm())) * 180.0 / M_PI;
    const bool was_created = map.keyframe(kf_ids[0]).line_landmark[m.index1] >= 0;
    if (angle_deg > 1.2) {
      EXPECT_TRUE(was_created) << "plane angle " << angle_deg;
    } else if (angle_deg < 0.8) {
      EXPECT_FALSE(was_created) << "plane angle " << angle_deg;
    }
  }
  for (const int id : created) {
    const LineLandmark& l = map.line(id);
    ASSERT_EQ(l.observations.size(), 2u);
    const int segment = segment_of_line[0][l.observations[0].index];
    const auto& truth = s.segments[segment];
    EXPECT_LT(testing::sameLineError(l.line_world, testing::lineOf(truth)), 1e-9);
    // Trimmed extent: 5 % .. 90 % of the true segment (union of both views).
    const Eigen::Vector3d p05 = truth.a + 0.05 * (truth.b - truth.a), p90 = truth.a + 0.9 * (truth.b - truth.a);
    const bool same_order = (l.start_world - p05).norm() < (l.start_world - p90).norm();
    EXPECT_LT(((same_order ? p05 : p90) - l.start_world).norm(), 1e-6);
    EXPECT_LT(((same_order ? p90 : p05) - l.end_world).norm(), 1e-6);
    EXPECT_FALSE(l.from_fusion);
  }
  EXPECT_GT(map.covisibility().weight(kf_ids[0], kf_ids[1]), 0);
  // Associated segments are not triangulated twice.
  EXPECT_TRUE(createLineLandmarks(map, kf_ids[0], kf_ids[1], matches, s.K).empty());
  // Out-of-range matches are ignored, not fatal.
  EXPECT_TRUE(createLineLandmarks(map, kf_ids[0], kf_ids[1], {{999, 0, 0}, {0, -1, 0}}, s.K).empty());
}

}  // namespace
}  // namespace lvslam::visual
