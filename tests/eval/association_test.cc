#include "lvslam/eval/association.h"

#include <set>

#include <gtest/gtest.h>

#include "lvslam/core/error.h"

namespace lvslam::eval {
namespace {

Trajectory stamped(const std::vector<double>& times) {
  Trajectory traj;
  for (const double t : times) traj.push_back({t, Eigen::Isometry3d::Identity()});
  return traj;
}

TEST(Association, UnequalRatesPickTheNearestStamp) {
  std::vector<double> gt_times, est_times;
  for (int k = 0; k <= 200; ++k) gt_times.push_back(0.01 * k);        // 100 Hz
  for (int k = 0; k < 20; ++k) est_times.push_back(0.003 + 0.1 * k);  // 10 Hz, 3 ms late
  const auto pairs = associateByTime(stamped(gt_times), stamped(est_times), 0.02);
  ASSERT_EQ(pairs.size(), 20u);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    EXPECT_EQ(pairs[k].est_index, k);
    EXPECT_EQ(pairs[k].gt_index, 10 * k);  // 3 ms from 10k, 7 ms from 10k+1
  }
}

TEST(Association, HigherRateEstimateIsSearchedFromTheGroundTruth) {
  const auto pairs = associateByTime(stamped({1.0, 2.0}), stamped({0.9, 0.995, 1.1, 2.004, 2.5}), 0.02);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0].gt_index, 0u);
  EXPECT_EQ(pairs[0].est_index, 1u);
  EXPECT_EQ(pairs[1].gt_index, 1u);
  EXPECT_EQ(pairs[1].est_index, 3u);
}

TEST(Association, RejectsStampsFurtherThanMaxDt) {
  const auto pairs = associateByTime(stamped({0.0, 1.0, 2.0, 3.0}), stamped({0.01, 1.05, 2.019, 3.5}), 0.02);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0].gt_index, 0u);
  EXPECT_EQ(pairs[1].gt_index, 2u);
  EXPECT_EQ(pairs[1].est_index, 2u);
}

TEST(Association, NoPoseIsUsedTwice) {
  // evo would give gt[1] to both 0.9 and 1.05; the closer one keeps it.
  const auto pairs =
      associateByTime(stamped({0.0, 1.0, 2.0, 3.0, 4.0, 5.0}), stamped({0.0, 0.9, 1.05, 3.0}), 0.2);
  ASSERT_EQ(pairs.size(), 3u);
  std::set<std::size_t> gt_used, est_used;
  for (const IndexPair& p : pairs) {
    EXPECT_TRUE(gt_used.insert(p.gt_index).second);
    EXPECT_TRUE(est_used.insert(p.est_index).second);
  }
  EXPECT_EQ(pairs[1].gt_index, 1u);
  EXPECT_EQ(pairs[1].est_index, 2u);
  EXPECT_EQ(pairs[2].gt_index, 3u);
  EXPECT_EQ(pairs[2].est_index, 3u);
}

TEST(Association, TimeStampsThatDoNotIncreaseAreAnError) {
  EXPECT_THROW(associateByTime(stamped({0.0, 2.0, 1.0}), stamped({0.0, 1.0, 2.0}), 0.02), Error);
}

}  // namespace
}  // namespace lvslam::eval
