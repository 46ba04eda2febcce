#include "lvslam/report/trajectory_errors.h"

#include <cmath>

#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace lvslam::report {
namespace {

// A 12 m arc at 10 Hz.
Trajectory arc() {
  Trajectory out;
  for (int i = 0; i < 120; ++i) {
    StampedPose pose;
    pose.t = 100.0 + 0.1 * i;
    const double a = 0.01 * i;
    pose.T_world_frame.translation() = Eigen::Vector3d(10.0 * std::sin(a), 10.0 * (1.0 - std::cos(a)), 0.0);
    pose.T_world_frame.linear() = Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    out.push_back(pose);
  }
  return out;
}

TEST(TrajectoryErrors, ARigidlyMovedEstimateHasNoErrorAfterAlignment) {
  const Trajectory gt = arc();
  Trajectory est = gt;
  const Eigen::Isometry3d T_est_gt = Eigen::Translation3d(1.0, -2.0, 0.5) * Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ());
  for (StampedPose& pose : est) pose.T_world_frame = T_est_gt * pose.T_world_frame;
  const TrajectoryErrors errors = computeTrajectoryErrors(gt, est, eval::Alignment::kSE3, "gt", "est");
  ASSERT_EQ(errors.series.size(), 5u);  // ATE, RPE 1 m and 10 m, translation and rotation
  EXPECT_EQ(errors.series[0].values.size(), 120u);
  EXPECT_LT(errors.series[0].stats.max, 1e-9);
  EXPECT_TRUE(errors.T_gt_est.R.isApprox(T_est_gt.rotation().transpose(), 1e-9));
  for (const ErrorSeries& s : errors.series) {
    ASSERT_EQ(s.t.size(), s.values.size()) << s.name;
    for (double t : s.t) EXPECT_TRUE(t >= 100.0 && t <= 112.0) << s.name << ": stamps are the estimate's";
  }
  EXPECT_GT(errors.series[1].values.size(), 5u) << "RPE 1 m pairs along a 12 m arc";
}

TEST(TrajectoryErrors, AnOffsetGrowsIntoTheAteOverTime) {
  const Trajectory gt = arc();
  Trajectory est = gt;
  // Drift along y, 1 cm per pose: after alignment the ends err most.
  for (std::size_t i = 0; i < est.size(); ++i) est[i].T_world_frame.translation().y() += 0.01 * static_cast<double>(i);
  const ErrorSeries ate = computeTrajectoryErrors(gt, est, eval::Alignment::kNone, "gt", "est").series[0];
  EXPECT_NEAR(ate.values.front(), 0.0, 1e-12);
  EXPECT_NEAR(ate.values.back(), 1.19, 1e-9);
  EXPECT_NEAR(ate.stats.max, 1.19, 1e-9);
}

TEST(TrajectoryErrors, TrajectoriesThatDoNotMeetInTimeAreNamed) {
  Trajectory late = arc();
  for (StampedPose& pose : late) pose.t += 1000.0;
  const std::string message = testing::errorMessageOf(
      [&] { computeTrajectoryErrors(arc(), late, eval::Alignment::kSE3, "gt.tum", "est.tum"); });
  EXPECT_NE(message.find("gt.tum vs est.tum"), std::string::npos) << message;
}

}  // namespace
}  // namespace lvslam::report
