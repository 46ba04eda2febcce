#pragma once
// Information matrices of camera poses, all for the right perturbation
// T_world_camera <- T_world_camera exp(xi), xi = (rho, phi) in the camera
// frame: how each subsystem's own uncertainty reaches the online estimator.
#include <Eigen/Geometry>

#include "lvslam/core/se3.h"

namespace lvslam::system {

// Adjoint of T for (rho, phi) twists: exp(Ad(T) xi) = T exp(xi) T^-1.
Matrix6d adjointSE3(const Eigen::Isometry3d& T);

// A LiDAR pose's information (body-frame perturbation of T_world_lidar, as
// the ICP gives it) carried to the camera: T_world_camera = T_world_lidar
// T_lidar_camera, so xi_camera = Ad(T_camera_lidar) xi_lidar.
Matrix6d lidarToCameraInformation(const Matrix6d& information_lidar, const Eigen::Isometry3d& T_camera_lidar);

// Pseudo-inverse of a symmetric positive semi-definite matrix and its rank:
// directions with eigenvalue below `relative_tolerance` x the largest are
// taken as carrying no information.
struct PseudoInverse {
  Matrix6d inverse = Matrix6d::Zero();
  Eigen::Matrix<double, 6, Eigen::Dynamic> range;  // orthonormal basis of the informative directions
  int rank = 0;
};
PseudoInverse pseudoInverse(const Matrix6d& symmetric, double relative_tolerance = 1e-12);

// The information of a covariance restricted to `range` (columns
// orthonormal): range (range^T C range)^-1 range^T; zero outside it.
Matrix6d informationOn(const Eigen::Matrix<double, 6, Eigen::Dynamic>& range, const Matrix6d& covariance);

// Isotropic translation and rotation noise as a covariance.
Matrix6d isotropicCovariance(double sigma_m, double sigma_rad);

// The chi-square quantile with `dof` (1..6) degrees of freedom at 99.9 %.
double chiSquare999(int dof);

// Right-tangent difference of two poses, log(T_a^-1 T_b) to first order.
Vector6d poseDifference(const Eigen::Isometry3d& T_a, const Eigen::Isometry3d& T_b);

}  // namespace lvslam::system
