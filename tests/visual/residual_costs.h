#pragma once
// Ceres wrappers of the residuals in src/lvslam/visual/residuals/ and the two
// tangent spaces they live on, for the tests only: with them Ceres' numeric
// differentiation checks each analytic Jacobian (residuals_test.cc). The
// local BA calls the residuals' evaluate functions directly
// (optimize/bundle_adjustment.cc), on the same two updates.
//
// Pose blocks are [t, q] with the left SE3 update T <- expSE3(delta) T. The
// cost functions write d(residual)/d(delta) into the first 6 of the 7 pose
// Jacobian columns and zero into the last; Se3LeftManifold's PlusJacobian
// is [I6; 0] (VINS-Mono's convention). Line blocks are unit Plücker (m, d)
// with the true 6x4 PlusJacobian of the orthonormal update.
#include <algorithm>
#include <cmath>

#include <ceres/manifold.h>
#include <ceres/sized_cost_function.h>
#include <Eigen/Dense>

#include "lvslam/core/se3.h"
#include "lvslam/visual/geometry/orthonormal_line.h"
#include "lvslam/visual/residuals/line_direction.h"
#include "lvslam/visual/residuals/line_reprojection.h"
#include "lvslam/visual/residuals/point_depth.h"
#include "lvslam/visual/residuals/point_reprojection.h"
#include "lvslam/visual/residuals/pose_block.h"
#include "lvslam/visual/residuals/pose_prior.h"

namespace lvslam::visual::testing {

// Writes d(residual)/d(delta) of a left SE3 update into the first 6 of the 7
// columns of a pose block's Jacobian (the 7th is zero: Se3LeftManifold's
// PlusJacobian is [I6; 0]).
template <int Rows>
inline void writePoseJacobian(const Eigen::Matrix<double, Rows, kPoseTangentSize>& J_tangent, double* out) {
  Eigen::Map<Eigen::Matrix<double, Rows, kPoseBlockSize, Eigen::RowMajor>> J(out);
  J.template leftCols<kPoseTangentSize>() = J_tangent;
  J.col(kPoseTangentSize).setZero();
}

class Se3LeftManifold final : public ceres::Manifold {
 public:
  int AmbientSize() const override { return kPoseBlockSize; }
  int TangentSize() const override { return kPoseTangentSize; }

  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override {
    const Vector6d d = Eigen::Map<const Vector6d>(delta);
    const PoseBlock out = toPoseBlock(expSE3(d) * fromPoseBlock(x));
    std::copy(out.begin(), out.end(), x_plus_delta);
    return true;
  }
  bool PlusJacobian(const double*, double* jacobian) const override {
    Eigen::Map<Eigen::Matrix<double, 7, 6, Eigen::RowMajor>> J(jacobian);
    J.setZero();
    J.topRows<6>().setIdentity();
    return true;
  }
  bool Minus(const double* y, const double* x, double* y_minus_x) const override {
    Eigen::Map<Vector6d>{y_minus_x} = logSE3(fromPoseBlock(y) * fromPoseBlock(x).inverse());
    return true;
  }
  bool MinusJacobian(const double*, double* jacobian) const override {
    Eigen::Map<Eigen::Matrix<double, 6, 7, Eigen::RowMajor>> J(jacobian);
    J.setZero();
    J.leftCols<6>().setIdentity();
    return true;
  }
};

class OrthonormalLineManifold final : public ceres::Manifold {
 public:
  int AmbientSize() const override { return kLineBlockSize; }
  int TangentSize() const override { return kLineTangentSize; }

  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override {
    const OrthonormalLine o = orthonormal(x).plus(Eigen::Map<const Eigen::Vector4d>(delta));
    Eigen::Map<Vector6d>{x_plus_delta} = o.toPlucker().vector();
    return true;
  }
  bool PlusJacobian(const double* x, double* jacobian) const override {
    Eigen::Map<Eigen::Matrix<double, 6, 4, Eigen::RowMajor>>{jacobian} =
        orthonormalPlusJacobian(orthonormal(x));
    return true;
  }
  bool Minus(const double* y, const double* x, double* y_minus_x) const override {
    Eigen::Map<Eigen::Vector4d>{y_minus_x} = orthonormal(x).minus(orthonormal(y));
    return true;
  }
  bool MinusJacobian(const double* x, double* jacobian) const override {
    const Eigen::Matrix<double, 6, 4> J = orthonormalPlusJacobian(orthonormal(x));
    Eigen::Map<Eigen::Matrix<double, 4, 6, Eigen::RowMajor>>{jacobian} =
        J.completeOrthogonalDecomposition().pseudoInverse();
    return true;
  }

 private:
  static OrthonormalLine orthonormal(const double* x) {
    return OrthonormalLine::fromPlucker(PluckerLine::fromVector(Eigen::Map<const Vector6d>(x)));
  }
};

// Blocks: pose [t, q] (Se3LeftManifold convention), point p_w (3).
class PointReprojectionCost final : public ceres::SizedCostFunction<2, kPoseBlockSize, 3> {
 public:
  PointReprojectionCost(const Eigen::Vector2d& observed, const PinholeIntrinsics& K, double sqrt_info)
      : observed_(observed), K_(K), sqrt_info_(sqrt_info) {}

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const Eigen::Isometry3d T = fromPoseBlock(parameters[0]);
    const Eigen::Vector3d p_w = Eigen::Map<const Eigen::Vector3d>(parameters[1]);
    Eigen::Vector2d r;
    Eigen::Matrix<double, 2, 6> J_pose;
    Eigen::Matrix<double, 2, 3> J_point;
    const bool want_pose = jacobians && jacobians[0];
    const bool want_point = jacobians && jacobians[1];
    if (!PointReprojection::evaluate(T.linear(), T.translation(), p_w, observed_, K_, sqrt_info_, r,
                                     want_pose ? &J_pose : nullptr, want_point ? &J_point : nullptr)) {
      return false;
    }
    Eigen::Map<Eigen::Vector2d>{residuals} = r;
    if (want_pose) writePoseJacobian(J_pose, jacobians[0]);
    if (want_point) Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>>{jacobians[1]} = J_point;
    return true;
  }

 private:
  Eigen::Vector2d observed_;
  PinholeIntrinsics K_;
  double sqrt_info_;
};

// Blocks: pose [t, q] (Se3LeftManifold convention), point p_w (3). Two rows,
// the second always 0 (the shape Ceres' BA once needed).
class PointDepthCost final : public ceres::SizedCostFunction<2, kPoseBlockSize, 3> {
 public:
  PointDepthCost(double depth, double inv_sigma) : depth_(depth), inv_sigma_(inv_sigma) {}

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const Eigen::Isometry3d T = fromPoseBlock(parameters[0]);
    const Eigen::Vector3d p_w = Eigen::Map<const Eigen::Vector3d>(parameters[1]);
    Eigen::Matrix<double, 1, 6> J_pose;
    Eigen::Matrix<double, 1, 3> J_point;
    const bool want_pose = jacobians && jacobians[0];
    const bool want_point = jacobians && jacobians[1];
    if (!PointDepth::evaluate(T.linear(), T.translation(), p_w, depth_, inv_sigma_, residuals[0],
                              want_pose ? &J_pose : nullptr, want_point ? &J_point : nullptr)) {
      return false;
    }
    residuals[1] = 0.0;
    if (want_pose) {
      Eigen::Matrix<double, 2, 6> J = Eigen::Matrix<double, 2, 6>::Zero();
      J.row(0) = J_pose;
      writePoseJacobian(J, jacobians[0]);
    }
    if (want_point) {
      Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>> J{jacobians[1]};
      J.row(0) = J_point;
      J.row(1).setZero();
    }
    return true;
  }

 private:
  double depth_, inv_sigma_;
};

// Blocks: pose [t, q] (Se3LeftManifold convention), line (m, d) (OrthonormalLineManifold).
class LineReprojectionCost final
    : public ceres::SizedCostFunction<2, kPoseBlockSize, kLineBlockSize> {
 public:
  LineReprojectionCost(const Eigen::Vector2d& start, const Eigen::Vector2d& end,
                       const Eigen::Matrix3d& K_line, double sqrt_info)
      : start_h_(start.x(), start.y(), 1.0), end_h_(end.x(), end.y(), 1.0), K_line_(K_line),
        sqrt_info_(sqrt_info) {}

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const Eigen::Isometry3d T = fromPoseBlock(parameters[0]);
    const Vector6d L_w = Eigen::Map<const Vector6d>(parameters[1]);
    Eigen::Vector2d r;
    Eigen::Matrix<double, 2, 6> J_pose, J_line;
    const bool want_pose = jacobians && jacobians[0];
    const bool want_line = jacobians && jacobians[1];
    if (!LineReprojection::evaluate(T.linear(), T.translation(), L_w, start_h_, end_h_, K_line_,
                                    sqrt_info_, r, want_pose ? &J_pose : nullptr,
                                    want_line ? &J_line : nullptr)) {
      return false;
    }
    Eigen::Map<Eigen::Vector2d>{residuals} = r;
    if (want_pose) writePoseJacobian(J_pose, jacobians[0]);
    if (want_line) Eigen::Map<Eigen::Matrix<double, 2, 6, Eigen::RowMajor>>{jacobians[1]} = J_line;
    return true;
  }

 private:
  Eigen::Vector3d start_h_, end_h_;
  Eigen::Matrix3d K_line_;
  double sqrt_info_;
};

// Block: line (m, d) (OrthonormalLineManifold); only d enters.
class LineDirectionCost final : public ceres::SizedCostFunction<1, kLineBlockSize> {
 public:
  // fusion_direction need not be unit; it must not be zero.
  LineDirectionCost(const Eigen::Vector3d& fusion_direction, double weight)
      : fusion_unit_(fusion_direction.normalized()), weight_(weight) {}

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const Eigen::Vector3d d = Eigen::Map<const Eigen::Vector3d>(parameters[0] + 3);
    Eigen::Matrix<double, 1, 3> J_d;
    const bool want = jacobians && jacobians[0];
    if (!LineDirection::evaluate(d, fusion_unit_, weight_, residuals[0], want ? &J_d : nullptr)) {
      return false;
    }
    if (want) {
      Eigen::Map<Eigen::Matrix<double, 1, 6>> J(jacobians[0]);
      J.leftCols<3>().setZero();
      J.rightCols<3>() = J_d;
    }
    return true;
  }

 private:
  Eigen::Vector3d fusion_unit_;
  double weight_;
};

// Block: pose [t, q] (Se3LeftManifold convention).
class PosePriorCost final : public ceres::SizedCostFunction<6, kPoseBlockSize> {
 public:
  PosePriorCost(const Eigen::Isometry3d& prior_T_camera_world, double sigma_t, double sigma_r)
      : prior_(prior_T_camera_world), inv_sigma_t_(1.0 / sigma_t), inv_sigma_r_(1.0 / sigma_r) {}

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    Eigen::Matrix<double, 6, 1> r;
    Eigen::Matrix<double, 6, 6> J;
    const bool want = jacobians && jacobians[0];
    PosePrior::evaluate(fromPoseBlock(parameters[0]), prior_, inv_sigma_t_, inv_sigma_r_, r, want ? &J : nullptr);
    Eigen::Map<Eigen::Matrix<double, 6, 1>>{residuals} = r;
    if (want) writePoseJacobian<6>(J, jacobians[0]);
    return true;
  }

 private:
  Eigen::Isometry3d prior_;
  double inv_sigma_t_, inv_sigma_r_;
};

}  // namespace lvslam::visual::testing
