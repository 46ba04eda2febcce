// The relative-pose graph of the online estimator against closed forms.
#include "lvslam/system/online/pose_graph.h"

#include <array>

#include <ceres/manifold.h>
#include <ceres/product_manifold.h>
#include <gtest/gtest.h>

#include "lvslam/system/online/pose_information.h"
#include "lvslam/system/online/relative_pose_cost.h"

namespace lvslam::system {
namespace {

Eigen::Isometry3d translation(double x, double y, double z) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

Matrix6d diagonal(double t0, double t1, double t2, double r) {
  Vector6d d;
  d << t0, t1, t2, r, r, r;
  return d.asDiagonal();
}

// Two estimates of the same pose with known diagonal informations: the
// solution is their information-weighted mean, axis by axis.
TEST(PoseGraph, TwoFactorsGiveTheInformationWeightedMean) {
  std::vector<PoseNode> nodes{{Eigen::Isometry3d::Identity(), true}, {translation(0.5, 0.5, 0.5), false}};
  const Matrix6d a = diagonal(100.0, 400.0, 1.0, 1e4), b = diagonal(300.0, 100.0, 0.0, 1e4);
  std::vector<PoseFactor> factors{{0, 1, translation(1.0, 2.0, 3.0), a, FactorSource::kLidar},
                                  {0, 1, translation(1.2, 1.0, -1.0), b, FactorSource::kVisual}};
  PoseGraphSolveConfig config;
  config.huber_delta = 1e6;  // quadratic: the closed form
  config.max_iterations = 50;
  ASSERT_TRUE(solvePoseGraph(nodes, factors, config));
  const Eigen::Vector3d t = nodes[1].T_world_camera.translation();
  EXPECT_NEAR(t.x(), (100.0 * 1.0 + 300.0 * 1.2) / 400.0, 1e-6);
  EXPECT_NEAR(t.y(), (400.0 * 2.0 + 100.0 * 1.0) / 500.0, 1e-6);
  EXPECT_NEAR(t.z(), 3.0, 1e-6);  // b says nothing along z
  EXPECT_NEAR(rotationAngle(nodes[1].T_world_camera), 0.0, 1e-9);
}

// The covariance of a node held by one factor from a fixed node is the
// factor's inverse information, turned into the world frame by the node's
// rotation (translation and rotation alike); two factors add information.
TEST(PoseGraph, ANodesCovarianceIsItsInverseInformationInTheWorldFrame) {
  Eigen::Isometry3d T_z = translation(1.0, 2.0, 3.0);
  T_z.linear() = expSO3(Eigen::Vector3d(0.2, -0.4, 1.1));
  Vector6d d;
  d << 100.0, 400.0, 25.0, 1e4, 4e4, 9e4;
  const Matrix6d information = d.asDiagonal();
  std::vector<PoseNode> nodes{{Eigen::Isometry3d::Identity(), true}, {translation(0.9, 2.1, 3.0), false}};
  const std::vector<PoseFactor> factors{{0, 1, T_z, information, FactorSource::kLidar}};
  NodeCovariance covariance{1, std::nullopt};
  PoseGraphSolveConfig config;
  config.huber_delta = 1e6;
  config.max_iterations = 50;
  ASSERT_TRUE(solvePoseGraph(nodes, factors, config, &covariance));
  ASSERT_TRUE(covariance.covariance);
  Matrix6d R = Matrix6d::Zero();
  R.block<3, 3>(0, 0) = R.block<3, 3>(3, 3) = T_z.linear();
  const Matrix6d expected = R * information.inverse() * R.transpose();
  EXPECT_LT((*covariance.covariance - expected).norm(), 1e-6 * expected.norm()) << *covariance.covariance;

  // A second, equal factor halves it; the fixed node has none.
  const std::vector<PoseFactor> twice{factors[0], factors[0]};
  NodeCovariance halved{1, std::nullopt}, fixed{0, std::nullopt};
  ASSERT_TRUE(solvePoseGraph(nodes, twice, config, &halved));
  ASSERT_TRUE(halved.covariance);
  EXPECT_LT((*halved.covariance - 0.5 * expected).norm(), 1e-6 * expected.norm());
  ASSERT_TRUE(solvePoseGraph(nodes, factors, config, &fixed));
  EXPECT_FALSE(fixed.covariance);
}

TEST(PoseGraph, FixedNodesStayAndAChainIsExact) {
  std::vector<PoseNode> nodes{{translation(1, 0, 0), true}, {Eigen::Isometry3d::Identity(), false},
                              {Eigen::Isometry3d::Identity(), false}};
  Eigen::Isometry3d step = translation(0.1, 0.0, 0.0);
  step.linear() = expSO3(Eigen::Vector3d(0.0, 0.0, 0.3));
  const Matrix6d information = diagonal(1e4, 1e4, 1e4, 1e4);
  std::vector<PoseFactor> factors{{0, 1, step, information, FactorSource::kLidar},
                                  {1, 2, step, information, FactorSource::kLidar}};
  ASSERT_TRUE(solvePoseGraph(nodes, factors, {}));
  EXPECT_TRUE(nodes[0].T_world_camera.isApprox(translation(1, 0, 0)));
  const Eigen::Isometry3d expected = translation(1, 0, 0) * step * step;
  EXPECT_LT((nodes[2].T_world_camera.matrix() - expected.matrix()).norm(), 1e-8);
  EXPECT_NEAR(factorChiSquare(factors[1], nodes), 0.0, 1e-10);
}

// A rotation error is measured in the frame of `to`: a right perturbation
// exp(xi) of the node gives the residual xi.
TEST(PoseGraph, FactorErrorIsTheRightPerturbation) {
  const Eigen::Isometry3d T = translation(0.3, -0.2, 1.0);
  Vector6d xi;
  xi << 0.001, -0.002, 0.003, 0.0005, -0.0004, 0.0002;
  std::vector<PoseNode> nodes{{Eigen::Isometry3d::Identity(), true}, {T * expSE3(xi), false}};
  const PoseFactor f{0, 1, T, Matrix6d::Identity(), FactorSource::kVisual};
  EXPECT_LT((factorError(f, nodes) - xi).norm(), 1e-6);
}

// The written-out Jacobians against central differences through Ceres' own
// manifold (translation, then EigenQuaternionManifold), including a
// measurement more than half a turn from the poses' relative rotation,
// where the residual takes the quaternion's other sign.
TEST(PoseGraph, RelativePoseCostJacobiansMatchNumericOnesOnTheManifold) {
  Eigen::Isometry3d T_a = translation(0.4, -1.2, 2.0), T_b = translation(-0.3, 0.8, 1.1), Z = translation(0.5, 0.1, -0.7);
  T_a.linear() = expSO3(Eigen::Vector3d(0.3, -0.5, 0.9));
  T_b.linear() = expSO3(Eigen::Vector3d(-0.7, 0.2, 0.4));
  Matrix6d L = Matrix6d::Identity();
  L.block<3, 3>(0, 3) = 0.3 * Eigen::Matrix3d::Ones();
  L.diagonal() << 10.0, 20.0, 5.0, 50.0, 40.0, 30.0;
  for (const double turn : {0.2, 2.9}) {
    Z.linear() = expSO3(Eigen::Vector3d(turn, -0.1, 0.2));
    const RelativePoseCost cost(Z, L);
    const auto block = [](const Eigen::Isometry3d& T) {
      const Eigen::Quaterniond q(T.linear());
      return std::array<double, 7>{T.translation().x(), T.translation().y(), T.translation().z(),
                                   q.x(), q.y(), q.z(), q.w()};
    };
    std::array<std::array<double, 7>, 2> x{block(T_a), block(T_b)};
    std::array<Eigen::Matrix<double, 6, 7, Eigen::RowMajor>, 2> J_ambient;
    Vector6d r;
    const double* params[2] = {x[0].data(), x[1].data()};
    double* jacobians[2] = {J_ambient[0].data(), J_ambient[1].data()};
    ASSERT_TRUE(cost.Evaluate(params, r.data(), jacobians));
    const ceres::ProductManifold<ceres::EuclideanManifold<3>, ceres::EigenQuaternionManifold> manifold;
    for (int k = 0; k < 2; ++k) {
      Eigen::Matrix<double, 7, 6, Eigen::RowMajor> P;
      ASSERT_TRUE(manifold.PlusJacobian(x[k].data(), P.data()));
      const Matrix6d analytic = J_ambient[k] * P;
      Matrix6d numeric;
      const double h = 1e-6;
      for (int j = 0; j < 6; ++j) {
        Vector6d r_plus, r_minus;
        for (const double sign : {1.0, -1.0}) {
          Vector6d delta = Vector6d::Zero();
          delta(j) = sign * h;
          auto moved = x;
          ASSERT_TRUE(manifold.Plus(x[k].data(), delta.data(), moved[k].data()));
          const double* moved_params[2] = {moved[0].data(), moved[1].data()};
          ASSERT_TRUE(cost.Evaluate(moved_params, (sign > 0 ? r_plus : r_minus).data(), nullptr));
        }
        numeric.col(j) = (r_plus - r_minus) / (2.0 * h);
      }
      EXPECT_LT((analytic - numeric).norm(), 1e-6 * numeric.norm()) << "turn " << turn << " block " << k
                                                                      << "\n" << analytic << "\n\n" << numeric;
    }
  }
}

TEST(PoseInformation, LidarInformationMovesToTheCameraFrameByTheAdjoint) {
  // A LiDAR that knows only its own x: the camera (axes rotated, offset) knows
  // the same physical direction.
  Eigen::Isometry3d T_camera_lidar = Eigen::Isometry3d::Identity();
  T_camera_lidar.linear() << 0, -1, 0, 0, 0, -1, 1, 0, 0;
  T_camera_lidar.translation() = Eigen::Vector3d(0.05, -0.2, 0.1);
  Matrix6d H_lidar = Matrix6d::Zero();
  H_lidar(0, 0) = 1.0;
  const Matrix6d H_camera = lidarToCameraInformation(H_lidar, T_camera_lidar);
  // A camera-frame shift along the LiDAR's x (the camera's z) is seen fully ...
  Vector6d along = Vector6d::Zero();
  along.head<3>() = T_camera_lidar.linear() * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(along.dot(H_camera * along), 1.0, 1e-12);
  // ... a shift across it not at all.
  Vector6d across = Vector6d::Zero();
  across.head<3>() = T_camera_lidar.linear() * Eigen::Vector3d::UnitY();
  EXPECT_NEAR(across.dot(H_camera * across), 0.0, 1e-12);
  EXPECT_EQ(pseudoInverse(H_camera).rank, 1);
}

}  // namespace
}  // namespace lvslam::system
