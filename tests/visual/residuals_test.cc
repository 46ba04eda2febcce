#include <cmath>
#include <memory>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "lvslam/core/se3.h"
#include "lvslam/visual/geometry/line_projection.h"
#include "visual/residual_costs.h"

namespace lvslam::visual {
namespace {

using testing::LineDirectionCost;
using testing::LineReprojectionCost;
using testing::OrthonormalLineManifold;
using testing::PointDepthCost;
using testing::PointReprojectionCost;
using testing::PosePriorCost;
using testing::Se3LeftManifold;

const PinholeIntrinsics kK{450.0, 460.0, 320.0, 240.0};

Eigen::Isometry3d somePose() {
  Vector6d xi;
  xi << 0.3, -0.2, 0.4, 0.1, -0.25, 0.15;
  return expSE3(xi);
}

Eigen::Matrix3d Kmat() {
  Eigen::Matrix3d K;
  K << kK.fx, 0, kK.cx, 0, kK.fy, kK.cy, 0, 0, 1;
  return K;
}

// Compares the analytic tangent Jacobian (ambient Jacobian x PlusJacobian,
// what Ceres uses) with central differences through the manifolds' Plus.
void expectTangentJacobianMatchesNumeric(const ceres::CostFunction& cost,
                                         std::vector<std::vector<double>> blocks,
                                         const std::vector<const ceres::Manifold*>& manifolds,
                                         double tolerance) {
  const int rows = cost.num_residuals();
  const auto& sizes = cost.parameter_block_sizes();
  std::vector<const double*> params;
  for (auto& b : blocks) params.push_back(b.data());
  std::vector<std::vector<double>> jac(blocks.size());
  std::vector<double*> jac_ptr;
  for (size_t k = 0; k < blocks.size(); ++k) {
    jac[k].resize(rows * sizes[k]);
    jac_ptr.push_back(jac[k].data());
  }
  Eigen::VectorXd r0(rows);
  ASSERT_TRUE(cost.Evaluate(params.data(), r0.data(), jac_ptr.data()));
  for (size_t k = 0; k < blocks.size(); ++k) {
    const ceres::Manifold& M = *manifolds[k];
    const int ambient = sizes[k], tangent = M.TangentSize();
    std::vector<double> pj(ambient * tangent);
    ASSERT_TRUE(M.PlusJacobian(blocks[k].data(), pj.data()));
    const Eigen::MatrixXd P = Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(pj.data(), ambient, tangent);
    const Eigen::MatrixXd J = Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(jac[k].data(), rows, ambient) * P;
    const double h = 1e-6;
    for (int j = 0; j < tangent; ++j) {
      Eigen::VectorXd delta = Eigen::VectorXd::Zero(tangent);
      std::vector<double> xp(ambient), xm(ambient);
      delta[j] = h;
      M.Plus(blocks[k].data(), delta.data(), xp.data());
      delta[j] = -h;
      M.Plus(blocks[k].data(), delta.data(), xm.data());
      Eigen::VectorXd rp(rows), rm(rows);
      std::vector<const double*> pp = params, pm = params;
      pp[k] = xp.data();
      pm[k] = xm.data();
      ASSERT_TRUE(cost.Evaluate(pp.data(), rp.data(), nullptr));
      ASSERT_TRUE(cost.Evaluate(pm.data(), rm.data(), nullptr));
      const Eigen::VectorXd numeric = (rp - rm) / (2 * h);
      EXPECT_LT((numeric - J.col(j)).norm(), tolerance * std::max(1.0, numeric.norm()))
          << "block " << k << " tangent column " << j << "\nnumeric " << numeric.transpose()
          << "\nanalytic " << J.col(j).transpose();
    }
  }
}

std::vector<double> poseVector(const Eigen::Isometry3d& T) {
  const PoseBlock b = toPoseBlock(T);
  return std::vector<double>(b.begin(), b.end());
}

std::vector<double> lineVector(const PluckerLine& L) {
  const Vector6d v = L.vector().normalized();
  return std::vector<double>(v.data(), v.data() + 6);
}

TEST(Se3LeftManifold, PlusAndMinusAreInverse) {
  const Se3LeftManifold M;
  const std::vector<double> x = poseVector(somePose());
  Vector6d delta;
  delta << 0.05, -0.02, 0.1, 0.03, 0.01, -0.04;
  std::vector<double> y(7);
  ASSERT_TRUE(M.Plus(x.data(), delta.data(), y.data()));
  EXPECT_TRUE(fromPoseBlock(y.data()).isApprox(expSE3(delta) * somePose(), 1e-12));
  Vector6d back;
  ASSERT_TRUE(M.Minus(y.data(), x.data(), back.data()));
  EXPECT_LT((back - delta).norm(), 1e-12);
}

TEST(OrthonormalLineManifold, PlusJacobianIsTheTrueDerivative) {
  const OrthonormalLineManifold M;
  const std::vector<double> x = lineVector(PluckerLine::fromPoints({1, 2, 5}, {-1, 0.5, 6}));
  std::vector<double> pj(24);
  ASSERT_TRUE(M.PlusJacobian(x.data(), pj.data()));
  const Eigen::Matrix<double, 6, 4, Eigen::RowMajor> P(pj.data());
  for (int j = 0; j < 4; ++j) {
    Eigen::Vector4d d = Eigen::Vector4d::Zero();
    Vector6d xp, xm;
    d[j] = 1e-6;
    M.Plus(x.data(), d.data(), xp.data());
    d[j] = -1e-6;
    M.Plus(x.data(), d.data(), xm.data());
    EXPECT_LT(((xp - xm) / 2e-6 - P.col(j)).norm(), 1e-8);
  }
  Eigen::Vector4d delta(0.02, -0.01, 0.03, 0.05), back;
  Vector6d y;
  M.Plus(x.data(), delta.data(), y.data());
  M.Minus(y.data(), x.data(), back.data());
  EXPECT_LT((back - delta).norm(), 1e-12);
  // Plus(x, 0) = x for a unit-norm block.
  const Eigen::Vector4d zero = Eigen::Vector4d::Zero();
  M.Plus(x.data(), zero.data(), y.data());
  EXPECT_LT((y - Eigen::Map<const Vector6d>(x.data())).norm(), 1e-12);
}

TEST(PointReprojectionCost, ZeroAtTheTrueProjectionAndJacobiansMatch) {
  const Eigen::Isometry3d T = somePose();
  const Eigen::Vector3d p_w = T.inverse() * Eigen::Vector3d(0.4, -0.3, 4.0);
  const Eigen::Vector2d obs = (Kmat() * (T * p_w)).hnormalized();
  const PointReprojectionCost exact(obs, kK, 1.0);
  std::vector<double> pose = poseVector(T), point(p_w.data(), p_w.data() + 3);
  const double* params[] = {pose.data(), point.data()};
  Eigen::Vector2d r;
  ASSERT_TRUE(exact.Evaluate(params, r.data(), nullptr));
  EXPECT_LT(r.norm(), 1e-9);
  // Off by (3, -2) pixels with sqrt_info 0.5.
  const PointReprojectionCost off(obs + Eigen::Vector2d(3, -2), kK, 0.5);
  ASSERT_TRUE(off.Evaluate(params, r.data(), nullptr));
  EXPECT_LT((r - Eigen::Vector2d(-1.5, 1.0)).norm(), 1e-9);
  const Se3LeftManifold pose_m;
  const ceres::EuclideanManifold<3> point_m;
  expectTangentJacobianMatchesNumeric(off, {pose, point}, {&pose_m, &point_m}, 1e-6);
  // Behind the camera: evaluation fails instead of giving a mirrored residual.
  const Eigen::Vector3d behind = T.inverse() * Eigen::Vector3d(0.4, -0.3, -4.0);
  std::vector<double> point_behind(behind.data(), behind.data() + 3);
  const double* params_behind[] = {pose.data(), point_behind.data()};
  EXPECT_FALSE(exact.Evaluate(params_behind, r.data(), nullptr));
}

TEST(PointDepthCost, WhitenedDepthErrorAndJacobiansMatch) {
  const Eigen::Isometry3d T = somePose();
  const Eigen::Vector3d p_c(0.7, -0.4, 3.5);
  const Eigen::Vector3d p_w = T.inverse() * p_c;
  std::vector<double> pose = poseVector(T), point(p_w.data(), p_w.data() + 3);
  const double* params[] = {pose.data(), point.data()};
  double r[2] = {1.0, 1.0};
  const PointDepthCost exact(3.5, 1.0 / (0.02 * 3.5));
  ASSERT_TRUE(exact.Evaluate(params, r, nullptr));
  EXPECT_NEAR(r[0], 0.0, 1e-9);
  EXPECT_EQ(r[1], 0.0);  // the padding row (Ceres' 2-row Schur kernels)
  // LiDAR says 3.4 m with sigma 0.068 m: (3.5 - 3.4) / 0.068.
  const PointDepthCost off(3.4, 1.0 / (0.02 * 3.4));
  ASSERT_TRUE(off.Evaluate(params, r, nullptr));
  EXPECT_NEAR(r[0], 0.1 / 0.068, 1e-9);
  EXPECT_EQ(r[1], 0.0);
  const Se3LeftManifold pose_m;
  const ceres::EuclideanManifold<3> point_m;
  expectTangentJacobianMatchesNumeric(off, {pose, point}, {&pose_m, &point_m}, 1e-6);
  // A point off the optical axis on every side exercises every Jacobian column.
  const Eigen::Vector3d p_w2 = T.inverse() * Eigen::Vector3d(-1.2, 0.9, 2.0);
  expectTangentJacobianMatchesNumeric(off, {pose, std::vector<double>(p_w2.data(), p_w2.data() + 3)},
                                      {&pose_m, &point_m}, 1e-6);
  // Behind the camera: no residual.
  const Eigen::Vector3d behind = T.inverse() * Eigen::Vector3d(0.7, -0.4, -3.5);
  std::vector<double> point_behind(behind.data(), behind.data() + 3);
  const double* params_behind[] = {pose.data(), point_behind.data()};
  EXPECT_FALSE(exact.Evaluate(params_behind, r, nullptr));
}

TEST(PosePriorCost, ZeroAtThePriorWhitenedErrorsAndJacobiansMatch) {
  const Eigen::Isometry3d T = somePose();
  std::vector<double> pose = poseVector(T);
  const double* params[] = {pose.data()};
  Eigen::Matrix<double, 6, 1> r;
  const PosePriorCost exact(T, 0.01, 0.005);
  ASSERT_TRUE(exact.Evaluate(params, r.data(), nullptr));
  EXPECT_LT(r.norm(), 1e-9);
  // The prior's camera centre 3 cm off along the world x axis, its rotation
  // 0.01 rad off about the camera's y axis: residual (-3, 0, 0, 0, -2, 0).
  const Eigen::Isometry3d centre_shift(Eigen::Translation3d(0.03, 0.0, 0.0));
  Eigen::Isometry3d prior = T * centre_shift.inverse();  // T_cw * T_world_world'
  Eigen::Isometry3d rot = Eigen::Isometry3d::Identity();
  rot.linear() = expSO3(Eigen::Vector3d(0.0, 0.01, 0.0));
  prior = rot * prior;  // rotate about the camera's own y axis
  const PosePriorCost off(prior, 0.01, 0.005);
  ASSERT_TRUE(off.Evaluate(params, r.data(), nullptr));
  EXPECT_NEAR(r[0], -3.0, 1e-6);
  EXPECT_NEAR(r[1], 0.0, 1e-6);
  EXPECT_NEAR(r[2], 0.0, 1e-6);
  EXPECT_NEAR(r[3], 0.0, 1e-9);
  EXPECT_NEAR(r[4], -2.0, 1e-9);
  EXPECT_NEAR(r[5], 0.0, 1e-9);
  const Se3LeftManifold pose_m;
  expectTangentJacobianMatchesNumeric(off, {pose}, {&pose_m}, 1e-6);
  // Far from the prior (0.8 rad) J_l^-1 is not the identity: still exact.
  Vector6d xi;
  xi << 0.5, -0.3, 0.2, 0.4, 0.6, -0.3;
  const PosePriorCost far(expSE3(xi) * T, 0.02, 0.01);
  expectTangentJacobianMatchesNumeric(far, {pose}, {&pose_m}, 1e-6);
}

TEST(LineReprojectionCost, EndpointDistancesAndJacobiansMatch) {
  const Eigen::Isometry3d T = somePose();
  const Eigen::Isometry3d T_w_c = T.inverse();
  const Eigen::Vector3d A = T_w_c * Eigen::Vector3d(-1.0, 0.5, 4.0), B = T_w_c * Eigen::Vector3d(1.5, -0.2, 6.0);
  const PluckerLine L = PluckerLine::fromPoints(A, B);
  const Eigen::Matrix3d K_line = lineProjectionMatrix(kK.fx, kK.fy, kK.cx, kK.cy);
  const Eigen::Vector2d a = (Kmat() * (T * A)).hnormalized(), b = (Kmat() * (T * B)).hnormalized();
  std::vector<double> pose = poseVector(T), line = lineVector(L);
  const double* params[] = {pose.data(), line.data()};
  Eigen::Vector2d r;
  const LineReprojectionCost exact(a, b, K_line, 1.0);
  ASSERT_TRUE(exact.Evaluate(params, r.data(), nullptr));
  EXPECT_LT(r.norm(), 1e-9);
  // Endpoints moved 2 px and 5 px along the image normal of the line: the
  // residual is exactly those signed distances.
  const Eigen::Vector2d n = Eigen::Vector2d(-(b - a).y(), (b - a).x()).normalized();
  const LineReprojectionCost off(a + 2.0 * n, b - 5.0 * n, K_line, 1.0);
  ASSERT_TRUE(off.Evaluate(params, r.data(), nullptr));
  EXPECT_NEAR(std::abs(r[0]), 2.0, 1e-9);
  EXPECT_NEAR(std::abs(r[1]), 5.0, 1e-9);
  EXPECT_LT(r[0] * r[1], 0.0);
  const Se3LeftManifold pose_m;
  const OrthonormalLineManifold line_m;
  expectTangentJacobianMatchesNumeric(off, {pose, line}, {&pose_m, &line_m}, 1e-6);
}

TEST(LineDirectionCost, ZeroWhenParallelEitherWayAndGrowsWithTheAngle) {
  const Eigen::Vector3d A(1, 2, 5), B(-1, 0.5, 6);
  const PluckerLine L = PluckerLine::fromPoints(A, B);
  std::vector<double> line = lineVector(L);
  const double* params[] = {line.data()};
  double r = 0.0;
  ASSERT_TRUE(LineDirectionCost(L.d * 3.0, 1.0).Evaluate(params, &r, nullptr));
  EXPECT_NEAR(r, 0.0, 1e-12);
  ASSERT_TRUE(LineDirectionCost(-L.d, 1.0).Evaluate(params, &r, nullptr));
  EXPECT_NEAR(r, 0.0, 1e-12);
  // Rotate d_fu away from d by growing angles about an axis normal to d.
  const Eigen::Vector3d axis = L.d.cross(Eigen::Vector3d::UnitZ()).normalized();
  double previous = -1.0;
  for (const double deg : {1.0, 5.0, 20.0, 45.0, 80.0, 90.0}) {
    const Eigen::Vector3d d_fu = Eigen::AngleAxisd(deg * M_PI / 180.0, axis) * L.d;
    ASSERT_TRUE(LineDirectionCost(d_fu, 2.0).Evaluate(params, &r, nullptr));
    EXPECT_NEAR(r, 2.0 * (1.0 - std::cos(deg * M_PI / 180.0)), 1e-12);
    EXPECT_GT(r, previous);
    previous = r;
    double r_anti = 0.0;
    ASSERT_TRUE(LineDirectionCost(-d_fu, 2.0).Evaluate(params, &r_anti, nullptr));
    EXPECT_NEAR(r_anti, r, 1e-12);
  }
  const OrthonormalLineManifold line_m;
  for (const double deg : {10.0, 60.0, 130.0}) {
    const Eigen::Vector3d d_fu = Eigen::AngleAxisd(deg * M_PI / 180.0, axis) * L.d;
    expectTangentJacobianMatchesNumeric(LineDirectionCost(d_fu, 1.5), {line}, {&line_m}, 1e-6);
  }
}

}  // namespace
}  // namespace lvslam::visual
