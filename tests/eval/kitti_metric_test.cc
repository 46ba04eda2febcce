#include "lvslam/eval/kitti_metric.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "eval/eval_test_trajectories.h"

namespace lvslam::eval {
namespace {

using testing::evenlySpaced;
using testing::posesAlongX;


// On a 1 m-step straight line of 1001 frames, a segment of length L from
// frame f ends at f + L + 1 (the devkit wants the path to exceed L), so it
// exists for f <= 999 - L: (999 - L) / 10 + 1 segments of L + 1 metres.
// Returns the segment-weighted mean of value(L).
template <typename F>
double meanOverDevkitSegments(F value) {
  double sum = 0.0;
  double count = 0.0;
  for (int L = 100; L <= 800; L += 100) {
    const double n = (999 - L) / 10 + 1;
    sum += n * value(static_cast<double>(L));
    count += n;
  }
  return sum / count;
}

TEST(KittiMetric, ScaleDriftGivesTheKnownPercentError) {
  const auto gt = posesAlongX(evenlySpaced(1001, 1.0));
  const auto est = posesAlongX(evenlySpaced(1001, 1.02));  // 2 % long
  const KittiMetric m = computeKittiMetric(gt, est, kKittiLengthsM);
  EXPECT_EQ(m.segments, 90u + 80 + 70 + 60 + 50 + 40 + 30 + 20);
  const double expected = meanOverDevkitSegments([](double L) { return 2.0 * (L + 1) / L; });
  EXPECT_NEAR(m.translation_percent, expected, 1e-9);
  EXPECT_NEAR(m.rotation_deg_per_m, 0.0, 1e-12);
}

TEST(KittiMetric, YawDriftGivesTheKnownRotationRate) {
  const double alpha_deg = 0.01;  // per frame
  const auto gt = posesAlongX(evenlySpaced(1001, 1.0));
  auto est = gt;
  for (std::size_t k = 0; k < est.size(); ++k)
    est[k].linear() = Eigen::AngleAxisd(alpha_deg * std::numbers::pi / 180.0 * static_cast<double>(k),
                                        Eigen::Vector3d::UnitZ())
                          .toRotationMatrix();
  const KittiMetric m = computeKittiMetric(gt, est, kKittiLengthsM);
  const double expected = meanOverDevkitSegments([&](double L) { return alpha_deg * (L + 1) / L; });
  EXPECT_NEAR(m.rotation_deg_per_m, expected, 1e-9);
}

TEST(KittiMetric, ShortSequenceHasOnlyShortSegments) {
  const auto gt = posesAlongX(evenlySpaced(21, 1.0));  // 20 m
  const auto est = posesAlongX(evenlySpaced(21, 1.1));
  const KittiMetric long_set = computeKittiMetric(gt, est, kKittiLengthsM);
  EXPECT_EQ(long_set.segments, 0u);
  EXPECT_TRUE(std::isnan(long_set.translation_percent));
  // Starts 0 and 10: lengths 1 and 5 from both, 10 only from frame 0.
  const KittiMetric short_set = computeKittiMetric(gt, est, kShortLengthsM);
  EXPECT_EQ(short_set.segments, 5u);
  const double expected = (2 * 10.0 * 2 / 1 + 2 * 10.0 * 6 / 5 + 10.0 * 11 / 10) / 5;
  EXPECT_NEAR(short_set.translation_percent, expected, 1e-9);
}

}  // namespace
}  // namespace lvslam::eval
