#include "lvslam/eval/line_accuracy.h"

#include <gtest/gtest.h>

namespace lvslam::eval {
namespace {

TEST(LineAccuracy, DistancesToSegmentAndLineAreExact) {
  const TrueSegment s{{0, 0, 0}, {2, 0, 0}};
  EXPECT_DOUBLE_EQ(distanceToLine({5, 3, 4}, s), 5.0);
  EXPECT_DOUBLE_EQ(distanceToSegment({5, 3, 4}, s), std::sqrt(9.0 + 9.0 + 16.0));
  EXPECT_DOUBLE_EQ(distanceToSegment({1, 0, 0.5}, s), 0.5);
}

TEST(LineAccuracy, MatchesTheNearestSegmentAndMeasuresEndpointsAndDirection) {
  const std::vector<TrueSegment> truth{{{0, 0, 0}, {0, 0, 2}}, {{1, 0, 0}, {1, 0, 2}}, {{0, 0, 0}, {1, 0, 0}}};
  // Near the second (vertical) segment, tilted by atan(0.02 / 1.5).
  const auto m = matchToNearestSegment({1.01, 0, 0.2}, {1.03, 0, 1.7}, truth);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->segment, 1u);
  EXPECT_NEAR(m->endpoint_distance[0], 0.01, 1e-12);
  EXPECT_NEAR(m->endpoint_distance[1], 0.03, 1e-12);
  EXPECT_NEAR(m->direction_error_deg, std::atan2(0.02, 1.5) * 180.0 / M_PI, 1e-9);
  EXPECT_FALSE(matchToNearestSegment({0, 0, 0}, {1, 0, 0}, {}));
}

TEST(LineAccuracy, SummaryGivesMediansOverEndpoints) {
  std::vector<LineMatch> matches(3);
  matches[0].endpoint_distance[0] = 0.01, matches[0].endpoint_distance[1] = 0.02, matches[0].direction_error_deg = 1;
  matches[1].endpoint_distance[0] = 0.03, matches[1].endpoint_distance[1] = 0.04, matches[1].direction_error_deg = 2;
  matches[2].endpoint_distance[0] = 0.05, matches[2].endpoint_distance[1] = 0.90, matches[2].direction_error_deg = 9;
  const AccuracySummary s = summarize(matches);
  EXPECT_EQ(s.lines, 3u);
  EXPECT_DOUBLE_EQ(s.median_direction_error_deg, 2.0);
  // Six endpoint distances; the nearest-rank median of an even count is the upper middle one.
  EXPECT_DOUBLE_EQ(s.median_endpoint_distance, 0.04);
  EXPECT_DOUBLE_EQ(quantile({}, 0.5), 0.0);
}

}  // namespace
}  // namespace lvslam::eval
