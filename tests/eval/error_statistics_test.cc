#include "lvslam/eval/error_statistics.h"

#include <cmath>

#include <gtest/gtest.h>

namespace lvslam::eval {
namespace {

TEST(ErrorStatistics, MatchesNumpyDefinitionsForEvenCount) {
  const ErrorStatistics s = computeStatistics({4.0, 1.0, 3.0, 2.0});
  EXPECT_EQ(s.count, 4u);
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.median, 2.5);  // mean of the two middle values
  EXPECT_DOUBLE_EQ(s.sse, 30.0);
  EXPECT_DOUBLE_EQ(s.rmse, std::sqrt(7.5));
  EXPECT_DOUBLE_EQ(s.std_dev, std::sqrt(1.25));  // population, ddof 0
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.max, 4.0);
}

TEST(ErrorStatistics, MedianOfOddCountIsTheMiddleValue) {
  EXPECT_DOUBLE_EQ(computeStatistics({5.0, 0.5, 9.0, 1.0, 7.0}).median, 5.0);
}

TEST(ErrorStatistics, EmptyHasZeroCountAndNaN) {
  const ErrorStatistics s = computeStatistics({});
  EXPECT_EQ(s.count, 0u);
  EXPECT_TRUE(std::isnan(s.rmse));
  EXPECT_TRUE(std::isnan(s.median));
}

}  // namespace
}  // namespace lvslam::eval
