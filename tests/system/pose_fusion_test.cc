#include "lvslam/system/pose_fusion.h"

#include <cmath>

#include <gtest/gtest.h>

#include "lvslam/system/output_correction.h"

namespace lvslam::system {
namespace {

Eigen::Vector3d centre(const Eigen::Isometry3d& T_camera_world) { return T_camera_world.inverse().translation(); }

const Eigen::Isometry3d kTCameraWorld = makePose(expSO3(Eigen::Vector3d(0.3, -1.1, 0.4)), Eigen::Vector3d(1, -2, 3));

// The same camera rotation, the centre moved by `offset` (world frame).
Eigen::Isometry3d shifted(const Eigen::Isometry3d& T_camera_world, const Eigen::Vector3d& offset) {
  return (T_camera_world.inverse() * makePose(Eigen::Matrix3d::Identity(), T_camera_world.linear() * offset))
      .inverse();
}

TEST(PoseFusion, EqualInformationMeetsHalfway) {
  const Eigen::Isometry3d a = kTCameraWorld;
  const Eigen::Isometry3d b = shifted(a, Eigen::Vector3d(0.01, -0.02, 0.004));
  const Matrix6d H = isotropicPoseInformation(0.005, 0.002);
  const Eigen::Isometry3d fused = fusePoses(a, H, b, H);
  EXPECT_LT((centre(fused) - 0.5 * (centre(a) + centre(b))).norm(), 1e-12);
  EXPECT_LT(rotationAngle(fused.inverse() * a), 1e-12);
  // Three times the information on b: a quarter of the way from b.
  const Eigen::Isometry3d toward_b = fusePoses(a, H, b, 3.0 * H);
  EXPECT_LT((centre(toward_b) - (0.25 * centre(a) + 0.75 * centre(b))).norm(), 1e-12);
}

// The same camera rotation, the centre moved by `offset` along the camera's axes.
Eigen::Isometry3d shiftedInCamera(const Eigen::Isometry3d& T_camera_world, const Eigen::Vector3d& offset) {
  return (T_camera_world.inverse() * makePose(Eigen::Matrix3d::Identity(), offset)).inverse();
}

// Each estimate knows some directions only (the camera's x from a, y and z
// from b): the fused pose takes each from the one that knows it.
TEST(PoseFusion, EachDirectionComesFromTheEstimateThatKnowsIt) {
  const Eigen::Isometry3d truth = kTCameraWorld;
  const Eigen::Isometry3d a = shiftedInCamera(truth, Eigen::Vector3d(0.0, 0.02, -0.01));  // wrong in y and z
  const Eigen::Isometry3d b = shiftedInCamera(truth, Eigen::Vector3d(0.03, 0.0, 0.0));    // wrong in x
  Matrix6d H_a = Matrix6d::Zero(), H_b = Matrix6d::Zero();
  H_a(0, 0) = 1e8;  // rho_x
  H_a.bottomRightCorner<3, 3>() = 1e8 * Eigen::Matrix3d::Identity();
  H_b(1, 1) = H_b(2, 2) = 1e8;  // rho_y, rho_z
  const Eigen::Isometry3d fused = fusePoses(a, H_a, b, H_b);
  EXPECT_LT((centre(fused) - centre(truth)).norm(), 1e-12);
  EXPECT_LT(rotationAngle(fused.inverse() * truth), 1e-12);
}

TEST(PoseFusion, WithoutInformationTheFirstEstimateStays) {
  const Eigen::Isometry3d a = kTCameraWorld;
  const Eigen::Isometry3d b = shifted(a, Eigen::Vector3d(0.1, 0.0, 0.0));
  EXPECT_TRUE(fusePoses(a, Matrix6d::Zero(), b, Matrix6d::Zero()).isApprox(a, 1e-12));
  EXPECT_TRUE(fusePoses(a, isotropicPoseInformation(0.01, 0.01), b, Matrix6d::Zero()).isApprox(a, 1e-12));
  // All information on b: b.
  EXPECT_LT((centre(fusePoses(a, Matrix6d::Zero(), b, isotropicPoseInformation(0.01, 0.01))) - centre(b)).norm(),
            1e-12);
}

// Without drift the LiDAR information is the isotropic one; with it, the
// variances grow linearly in the path (a random walk), so after s metres
// sigma^2 = sigma0^2 + drift^2 s, and a fused pose leans further toward the other estimate.
TEST(PoseFusion, LidarInformationShrinksWithThePathSinceTheAnchor) {
  PoseFusionConfig c;
  c.lidar_sigma_m = 0.005;
  c.lidar_sigma_deg = 0.15;
  c.lidar_drift_m = 0.0;
  c.lidar_drift_deg = 0.0;
  const Matrix6d H0 = isotropicPoseInformation(0.005, 0.15 * M_PI / 180.0);
  EXPECT_TRUE(lidarPoseInformation(c, 40.0).isApprox(H0, 1e-12));  // drift off
  c.lidar_drift_m = 0.003;
  c.lidar_drift_deg = 0.02;
  EXPECT_TRUE(lidarPoseInformation(c, 0.0).isApprox(H0, 1e-12));
  EXPECT_TRUE(lidarPoseInformation(c, -1.0).isApprox(H0, 1e-12));  // no negative paths
  const Matrix6d H = lidarPoseInformation(c, 16.0);
  const double var_m = 0.005 * 0.005 + 0.003 * 0.003 * 16.0;
  const double var_rad = std::pow(0.15 * M_PI / 180.0, 2) + std::pow(0.02 * M_PI / 180.0, 2) * 16.0;
  EXPECT_NEAR(H(0, 0), 1.0 / var_m, 1e-9 / var_m);
  EXPECT_NEAR(H(2, 2), 1.0 / var_m, 1e-9 / var_m);
  EXPECT_NEAR(H(4, 4), 1.0 / var_rad, 1e-9 / var_rad);
  EXPECT_EQ(H(0, 4), 0.0);
  // The visual estimate b, at the LiDAR's base information: halfway; with 16 m of drift, closer to b.
  const Eigen::Isometry3d a = kTCameraWorld;
  const Eigen::Isometry3d b = shifted(a, Eigen::Vector3d(0.01, 0.0, 0.0));
  const double w = (centre(fusePoses(a, H, b, H0)) - centre(a)).norm() / 0.01;
  EXPECT_NEAR(w, H0(0, 0) / (H0(0, 0) + H(0, 0)), 1e-9);
  EXPECT_GT(w, 0.5);
}

// A far scene's tracker information: a sideways shift (rho_x) and a turn
// about the camera's y (phi_y) trade against each other.
Matrix6d coupledInformation() {
  Matrix6d C = Matrix6d::Zero();  // covariance
  C.diagonal() << 4e-6, 2e-6, 9e-6, 1e-7, 2e-7, 1e-7;
  C(0, 4) = C(4, 0) = -0.9 * std::sqrt(4e-6 * 2e-7);
  C(1, 3) = C(3, 1) = 0.8 * std::sqrt(2e-6 * 1e-7);
  return C.inverse();
}

// Each block is the inverse of the covariance's block (the marginal), the
// cross terms are gone; an information without coupling stays as it is,
// directions it does not know included.
TEST(PoseFusion, DecoupledInformationKeepsTheMarginals) {
  const Matrix6d H = coupledInformation();
  const Matrix6d C = H.inverse();
  const Matrix6d D = decoupledInformation(H);
  const Eigen::Matrix3d D_t = D.topLeftCorner<3, 3>(), D_r = D.bottomRightCorner<3, 3>();
  const Eigen::Matrix3d C_t = C.topLeftCorner<3, 3>(), C_r = C.bottomRightCorner<3, 3>();
  EXPECT_TRUE(D_t.inverse().isApprox(C_t, 1e-9));
  EXPECT_TRUE(D_r.inverse().isApprox(C_r, 1e-9));
  const Eigen::Matrix3d cross_tr = D.topRightCorner<3, 3>(), cross_rt = D.bottomLeftCorner<3, 3>();
  EXPECT_EQ(cross_tr, Eigen::Matrix3d::Zero());
  EXPECT_EQ(cross_rt, Eigen::Matrix3d::Zero());
  // The marginal knows the shift less than the joint information does with the turn held.
  EXPECT_LT(D(0, 0), H(0, 0));
  Matrix6d partial = 1e6 * Matrix6d::Identity();
  partial(0, 0) = 0.0;  // the camera's x unknown
  EXPECT_TRUE(decoupledInformation(partial).isApprox(partial, 1e-12));
}

// Two estimates that agree on the centre and differ only in the turn: with
// the coupled information the fused centre moves sideways along the tie,
// with the decoupled one it stays where both put it.
TEST(PoseFusion, ARotationDifferenceMovesNoCentreWhenDecoupled) {
  const Eigen::Isometry3d lidar = kTCameraWorld;
  const Eigen::Isometry3d visual =
      (lidar.inverse() * makePose(expSO3(Eigen::Vector3d(0.0, 0.002, 0.0)), Eigen::Vector3d::Zero())).inverse();
  ASSERT_LT((centre(visual) - centre(lidar)).norm(), 1e-15);
  const Matrix6d H_lidar = isotropicPoseInformation(0.005, 0.15 * M_PI / 180.0);
  const Eigen::Isometry3d coupled = fusePoses(lidar, H_lidar, visual, coupledInformation());
  const Eigen::Isometry3d decoupled = fusePoses(lidar, H_lidar, visual, decoupledInformation(coupledInformation()));
  EXPECT_GT((centre(coupled) - centre(lidar)).norm(), 1e-4);
  EXPECT_LT((centre(decoupled) - centre(lidar)).norm(), 1e-6);
  EXPECT_GT(rotationAngle(decoupled * lidar.inverse()), 0.001);  // the turn still comes from vision
}

// The output follows the LiDAR exactly without a target, reaches a target
// by bounded steps, and returns to the LiDAR by bounded steps when the
// target goes (vision leaves).
TEST(OutputCorrection, TheCorrectionComesAndGoesByBoundedSteps) {
  const double max_m = 0.002, max_deg = 0.05;
  OutputCorrection out(max_m, max_deg);
  const auto lidar = [](int j) {
    return makePose(expSO3(Eigen::Vector3d(0.0, 0.0, 0.02 * j)), Eigen::Vector3d(0.03 * j, 0.01 * j, 0.0));
  };
  const Eigen::Isometry3d offset = makePose(expSO3(Eigen::Vector3d(0.0, 0.003, 0.0)), Eigen::Vector3d(0.009, 0, 0));
  EXPECT_TRUE(out.add(lidar(0), std::nullopt).isApprox(lidar(0), 1e-12));
  Eigen::Isometry3d previous_correction = Eigen::Isometry3d::Identity();
  for (int j = 1; j < 30; ++j) {
    const bool vision = j < 15;
    const Eigen::Isometry3d T = out.add(lidar(j), vision ? std::optional(lidar(j) * offset) : std::nullopt);
    const Eigen::Isometry3d correction = lidar(j).inverse() * T;
    const Eigen::Isometry3d change = previous_correction.inverse() * correction;
    EXPECT_LT(change.translation().norm(), max_m + 1e-12) << j;
    EXPECT_LT(rotationAngle(change) * 180.0 / M_PI, max_deg + 1e-9) << j;
    previous_correction = correction;
    // 9 mm at 2 mm per frame, 0.17 deg at 0.05: the target after 5 frames.
    if (j >= 5 && j < 15) {
      EXPECT_TRUE(correction.isApprox(offset, 1e-9)) << j;
    }
    if (j >= 20) {
      EXPECT_TRUE(T.isApprox(lidar(j), 1e-9)) << j;
    }
  }
}

}  // namespace
}  // namespace lvslam::system
