#include "lvslam/eval/umeyama.h"

#include <random>

#include <gtest/gtest.h>

#include "lvslam/core/error.h"
#include "lvslam/core/se3.h"

namespace lvslam::eval {
namespace {

Eigen::Matrix3Xd randomPoints(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coord(-20.0, 20.0);
  Eigen::Matrix3Xd points(3, count);
  for (int i = 0; i < count; ++i) points.col(i) = Eigen::Vector3d(coord(rng), coord(rng), coord(rng));
  return points;
}

Eigen::Matrix3Xd transformed(const Eigen::Matrix3Xd& points, const Eigen::Matrix3d& R,
                             const Eigen::Vector3d& t, double scale) {
  return ((scale * R * points).colwise() + t).eval();
}

const Eigen::Matrix3d kR = expSO3(Eigen::Vector3d(0.3, -1.2, 2.0));
const Eigen::Vector3d kT(4.0, -7.5, 1.25);

TEST(Umeyama, RecoversRigidTransformExactly) {
  const Eigen::Matrix3Xd from = randomPoints(30, 1);
  const Similarity3 s = umeyamaAlignment(from, transformed(from, kR, kT, 1.0), false);
  EXPECT_LT((s.R - kR).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((s.t - kT).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_EQ(s.scale, 1.0);
}

TEST(Umeyama, RecoversSimilarityTransformExactly) {
  const Eigen::Matrix3Xd from = randomPoints(30, 2);
  const Similarity3 s = umeyamaAlignment(from, transformed(from, kR, kT, 2.5), true);
  EXPECT_LT((s.R - kR).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((s.t - kT).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_NEAR(s.scale, 2.5, 1e-9);
}

TEST(Umeyama, RigidAlignmentIgnoresScaleDifference) {
  const Eigen::Matrix3Xd from = randomPoints(30, 3);
  const Similarity3 s = umeyamaAlignment(from, transformed(from, kR, kT, 2.5), false);
  EXPECT_EQ(s.scale, 1.0);
  EXPECT_LT((s.R - kR).cwiseAbs().maxCoeff(), 1e-9);  // rotation still recovered
}

TEST(Umeyama, NoisyPointsGiveTheKnownAnswerWithinTolerance) {
  const Eigen::Matrix3Xd from = randomPoints(500, 4);
  Eigen::Matrix3Xd to = transformed(from, kR, kT, 0.8);
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.02);
  for (int i = 0; i < to.cols(); ++i) to.col(i) += Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
  const Similarity3 s = umeyamaAlignment(from, to, true);
  EXPECT_LT(rotationAngle(makePose(Eigen::Matrix3d(s.R.transpose() * kR), Eigen::Vector3d::Zero())), 1e-3);
  EXPECT_LT((s.t - kT).norm(), 0.01);
  EXPECT_NEAR(s.scale, 0.8, 1e-3);
}

TEST(Umeyama, ReturnsAProperRotationForMirroredPoints) {
  // The best orthogonal fit to mirrored points is a reflection; Umeyama's S
  // must turn it into a rotation.
  const Eigen::Matrix3Xd from = randomPoints(20, 6);
  Eigen::Matrix3Xd to = from;
  to.row(2) *= -1.0;
  const Similarity3 s = umeyamaAlignment(from, to, false);
  EXPECT_NEAR(s.R.determinant(), 1.0, 1e-9);
  EXPECT_TRUE(isRotation(s.R, 1e-9));
}

TEST(Umeyama, AllPointsEqualIsAnError) {
  const Eigen::Matrix3Xd same = Eigen::Vector3d(1, 2, 3).replicate(1, 10);
  EXPECT_THROW(umeyamaAlignment(same, randomPoints(10, 7), false), Error);
}

}  // namespace
}  // namespace lvslam::eval
