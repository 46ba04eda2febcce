#include "lvslam/core/se3.h"

#include <cmath>

#include <gtest/gtest.h>

namespace lvslam {
namespace {

Vector6d twist(double a, double b, double c, double d, double e, double f) {
  Vector6d xi;
  xi << a, b, c, d, e, f;
  return xi;
}

TEST(Se3, ExpLogRoundTripOverAnglesUpToNearlyPi) {
  for (const double angle : {0.0, 1e-9, 1e-4, 0.3, 1.5, 3.0, M_PI - 1e-6}) {
    const Eigen::Vector3d axis = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
    Vector6d xi;
    xi << 0.4, -1.2, 2.5, angle * axis;
    const Vector6d back = logSE3(expSE3(xi));
    EXPECT_LT((back - xi).norm(), 1e-9) << "angle " << angle;
  }
}

TEST(Se3, ExpMatchesRodriguesAndClosedFormTranslation) {
  // Pure rotation about z by 90 deg with rho along x: the translation is
  // J_l(phi) rho = [sin t / t, (1 - cos t) / t, 0] for t = pi/2.
  const double t = M_PI / 2.0;
  const Eigen::Isometry3d T = expSE3(twist(1, 0, 0, 0, 0, t));
  EXPECT_NEAR(T.linear()(0, 1), -1.0, 1e-12);
  EXPECT_NEAR(T.linear()(1, 0), 1.0, 1e-12);
  EXPECT_NEAR(T.translation().x(), std::sin(t) / t, 1e-12);
  EXPECT_NEAR(T.translation().y(), (1.0 - std::cos(t)) / t, 1e-12);
  EXPECT_NEAR(T.translation().z(), 0.0, 1e-12);
}

TEST(Se3, ComposeAndInverseIdentities) {
  const Eigen::Isometry3d A = expSE3(twist(0.1, 0.2, 0.3, 0.4, -0.2, 0.9));
  const Eigen::Isometry3d B = expSE3(twist(-1.0, 2.0, 0.5, -0.3, 0.1, 0.2));
  EXPECT_TRUE((A * A.inverse()).isApprox(Eigen::Isometry3d::Identity(), 1e-12));
  EXPECT_TRUE(((A * B).inverse()).isApprox(B.inverse() * A.inverse(), 1e-12));
  const Eigen::Vector3d p(1.0, -2.0, 3.0);
  EXPECT_LT(((A * B) * p - A * (B * p)).norm(), 1e-12);
}

TEST(Se3, LeftJacobianInverseIsInverse) {
  for (const double s : {1e-7, 0.1, 1.0, 2.5}) {
    const Eigen::Vector3d phi = s * Eigen::Vector3d(0.2, -0.7, 0.4).normalized();
    EXPECT_LT((leftJacobianSO3(phi) * leftJacobianSO3Inverse(phi) - Eigen::Matrix3d::Identity()).norm(), 1e-9);
  }
}

TEST(Se3, IsRotationRejectsReflectionsScalesAndNan) {
  EXPECT_TRUE(isRotation(expSO3(Eigen::Vector3d(0.1, 0.2, 0.3))));
  EXPECT_FALSE(isRotation(-Eigen::Matrix3d::Identity()));
  EXPECT_FALSE(isRotation(1.01 * Eigen::Matrix3d::Identity()));
  Eigen::Matrix3d bad = Eigen::Matrix3d::Identity();
  bad(0, 0) = std::nan("");
  EXPECT_FALSE(isRotation(bad));
  const Eigen::Matrix3d noisy = expSO3(Eigen::Vector3d(0.3, 0.0, 0.1)) + 1e-4 * Eigen::Matrix3d::Ones();
  EXPECT_TRUE(isRotation(closestRotation(noisy), 1e-12));
}

TEST(Se3, IsRigidTransformNeedsAFiniteTranslationAndARotation) {
  Eigen::Isometry3d T = makePose(expSO3(Eigen::Vector3d(0.1, -0.2, 0.3)), Eigen::Vector3d(1, 2, 3));
  EXPECT_TRUE(isRigidTransform(T));
  Eigen::Isometry3d nan_translation = T;
  nan_translation.translation().y() = std::nan("");
  EXPECT_FALSE(isRigidTransform(nan_translation));
  Eigen::Isometry3d scaled = T;
  scaled.linear() *= 1.01;
  EXPECT_FALSE(isRigidTransform(scaled));
}

TEST(Se3, InterpolationIsSlerpPlusLerp) {
  const Eigen::Isometry3d A = makePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, 0));
  const Eigen::Isometry3d B =
      makePose(Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()).toRotationMatrix(), Eigen::Vector3d(2, 4, -6));
  const Eigen::Isometry3d M = interpolate(A, B, 0.25);
  EXPECT_NEAR(rotationAngle(M), 0.25, 1e-12);
  EXPECT_LT((M.translation() - Eigen::Vector3d(0.5, 1.0, -1.5)).norm(), 1e-12);
  EXPECT_TRUE(interpolate(A, B, 0.0).isApprox(A, 1e-12));
  EXPECT_TRUE(interpolate(A, B, 1.0).isApprox(B, 1e-12));
}

TEST(Se3, InterpolationAtTimeExtrapolatesAtConstantVelocity) {
  const Eigen::Isometry3d A = expSE3(twist(0.3, 0.1, 0.0, 0.0, 0.0, 0.2));
  const Eigen::Isometry3d B =
      makePose(A.linear() * Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
               A.translation() + Eigen::Vector3d(1.0, 0.5, 0.0));
  // Inside [t0, t1]: interpolation; at 2 t1: one more step of the same motion.
  const Eigen::Isometry3d mid = interpolateAtTime(10.5, 10.0, A, 11.0, B);
  EXPECT_TRUE(mid.isApprox(interpolate(A, B, 0.5), 1e-12));
  const Eigen::Isometry3d ahead = interpolateAtTime(12.0, 10.0, A, 11.0, B);
  EXPECT_NEAR(rotationAngle(A.inverse() * ahead), 0.2, 1e-12);
  EXPECT_LT((ahead.translation() - (A.translation() + Eigen::Vector3d(2.0, 1.0, 0.0))).norm(), 1e-12);
}

TEST(Se3, RotationAngleIsPreciseForTinyAngles) {
  const Eigen::Isometry3d T = makePose(expSO3(Eigen::Vector3d(0.0, 1e-7, 0.0)), Eigen::Vector3d::Zero());
  EXPECT_NEAR(rotationAngle(T), 1e-7, 1e-13);
}

// The left update is exp(delta) T, and it takes a rotation that has drifted
// off SO(3) (a long chain of products) back onto it.
TEST(Se3, LeftUpdateIsExpTimesTAndKeepsTheRotationOrthonormal) {
  const Eigen::Isometry3d T = expSE3(twist(0.3, -0.2, 0.5, 0.1, 0.4, -0.3));
  const Vector6d delta = twist(0.01, 0.02, -0.03, 0.002, -0.001, 0.003);
  EXPECT_TRUE(leftUpdate(delta, T).isApprox(expSE3(delta) * T, 1e-12));
  Eigen::Isometry3d drifted = T;
  drifted.linear() *= 1.0 + 1e-6;
  const Eigen::Matrix3d R = leftUpdate(Vector6d::Zero(), drifted).linear();
  EXPECT_LT((R * R.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-14);
  EXPECT_LT((R - T.linear()).norm(), 1e-6);  // back within the size of the drift
}

}  // namespace
}  // namespace lvslam
