#include "lvslam/eval/ate.h"

#include <cmath>

#include <gtest/gtest.h>

#include "eval/eval_test_trajectories.h"
#include "lvslam/core/error.h"

namespace lvslam::eval {
namespace {

using testing::makeSpiral;
using testing::posesOf;

std::vector<Eigen::Isometry3d> moved(const std::vector<Eigen::Isometry3d>& poses,
                                     const Eigen::Isometry3d& T, double scale = 1.0) {
  std::vector<Eigen::Isometry3d> out;
  for (Eigen::Isometry3d p : poses) {
    p.translation() = scale * p.translation();
    out.push_back(T * p);
  }
  return out;
}

const Eigen::Isometry3d kT = makePose(expSO3(Eigen::Vector3d(0.2, 0.4, -1.0)), Eigen::Vector3d(3, -2, 5));

TEST(Ate, RigidlyMovedEstimateHasZeroErrorAfterSe3Alignment) {
  const auto gt = posesOf(makeSpiral(60));
  const AteResult ate = computeAte(gt, moved(gt, kT), Alignment::kSE3);
  EXPECT_LT(ate.stats.max, 1e-6);
  EXPECT_EQ(ate.stats.count, 60u);
  // The alignment is the inverse of the applied motion.
  EXPECT_LT((ate.T_gt_est.R - kT.linear().transpose()).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(Ate, RigidlyMovedEstimateWithoutAlignmentHasThePointwiseOffset) {
  const auto gt = posesOf(makeSpiral(60));
  const auto est = moved(gt, kT);
  const AteResult ate = computeAte(gt, est, Alignment::kNone);
  for (std::size_t k = 0; k < gt.size(); ++k)
    EXPECT_NEAR(ate.errors[k], (kT * gt[k].translation() - gt[k].translation()).norm(), 1e-9);
}

TEST(Ate, PureOffsetWithoutAlignmentIsTheOffsetLength) {
  const auto gt = posesOf(makeSpiral(40));
  Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();
  offset.translation() = Eigen::Vector3d(0.3, -0.4, 1.2);  // length 1.3
  const ErrorStatistics s = computeAte(gt, moved(gt, offset), Alignment::kNone).stats;
  for (const double v : {s.rmse, s.mean, s.median, s.min, s.max}) EXPECT_NEAR(v, 1.3, 1e-9);
  EXPECT_NEAR(s.std_dev, 0.0, 1e-9);
  EXPECT_LT(computeAte(gt, moved(gt, offset), Alignment::kSE3).stats.max, 1e-6);
}

TEST(Ate, SimilarityIsRemovedBySim3AndItsScaleRecovered) {
  const auto gt = posesOf(makeSpiral(60));
  const auto est = moved(gt, kT, 0.4);  // a monocular estimate at 40 % scale
  const AteResult sim3 = computeAte(gt, est, Alignment::kSim3);
  EXPECT_LT(sim3.stats.max, 1e-6);
  EXPECT_NEAR(sim3.T_gt_est.scale, 1.0 / 0.4, 1e-9);
  const AteResult se3 = computeAte(gt, est, Alignment::kSE3);
  EXPECT_EQ(se3.T_gt_est.scale, 1.0);
  EXPECT_GT(se3.stats.rmse, 1.0);  // SE3 cannot undo the scale
}

// An odd, point-symmetric path whose middle pose is the centroid: moving that
// pose by v leaves the cross covariance symmetric, so the SE3 alignment is a
// pure shift by -v/n and the errors have a closed form.
TEST(Ate, OnePerturbedPoseGivesTheClosedFormStatistics) {
  std::vector<Eigen::Isometry3d> gt;
  for (int k = -10; k <= 10; ++k) {
    const double s = 0.3 * k;
    gt.push_back(makePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(s, std::sin(s), s * s * s)));
  }
  const double n = static_cast<double>(gt.size());  // 21
  auto est = gt;
  const Eigen::Vector3d v(0.6, 0.0, -0.8);  // length a = 1
  est[10].translation() += v;
  const double a = 1.0;

  const ErrorStatistics none = computeAte(gt, est, Alignment::kNone).stats;
  EXPECT_NEAR(none.mean, a / n, 1e-9);
  EXPECT_NEAR(none.rmse, a / std::sqrt(n), 1e-9);
  EXPECT_NEAR(none.median, 0.0, 1e-9);
  EXPECT_NEAR(none.max, a, 1e-9);
  EXPECT_NEAR(none.std_dev, a * std::sqrt(n - 1) / n, 1e-9);

  // Aligned: n-1 errors of a/n and one of a(n-1)/n.
  const ErrorStatistics se3 = computeAte(gt, est, Alignment::kSE3).stats;
  EXPECT_NEAR(se3.mean, 2 * a * (n - 1) / (n * n), 1e-6);
  EXPECT_NEAR(se3.rmse, a * std::sqrt(n - 1) / n, 1e-6);
  EXPECT_NEAR(se3.median, a / n, 1e-6);
  EXPECT_NEAR(se3.min, a / n, 1e-6);
  EXPECT_NEAR(se3.max, a * (n - 1) / n, 1e-6);
  EXPECT_NEAR(se3.sse, a * a * (n - 1) / n, 1e-6);
  EXPECT_NEAR(se3.std_dev, a / n * std::sqrt((n - 1) - 4 * (n - 1) * (n - 1) / (n * n)), 1e-6);
}

TEST(Ate, AllEstimatedPositionsEqualIsAnError) {
  const auto gt = posesOf(makeSpiral(10));
  const std::vector<Eigen::Isometry3d> est(10, Eigen::Isometry3d::Identity());
  EXPECT_THROW(computeAte(gt, est, Alignment::kSE3), Error);
  EXPECT_NO_THROW(computeAte(gt, est, Alignment::kNone));
}

}  // namespace
}  // namespace lvslam::eval
