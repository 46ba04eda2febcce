#pragma once
// MULLS multi-metric ICP (Pan et al. 2021, Sec. III-C): class-wise nearest
// neighbours in the local map, point-to-plane residuals for ground / facade /
// roof, point-to-line for pillar / beam, point-to-point for vertex, robust
// weights, Gauss-Newton on SE3 with degenerate directions held at the guess.
#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/core/se3.h"
#include "lvslam/lidar/feature_point.h"
#include "lvslam/lidar/lidar_config.h"
#include "lvslam/lidar/local_map.h"

namespace lvslam::lidar {

struct IcpResult {
  Eigen::Isometry3d T_world_lidar = Eigen::Isometry3d::Identity();
  int iterations = 0;
  std::size_t correspondences = 0;  // in the last iteration
  bool converged = false;
  bool degenerate = false;      // some direction of the normal matrix had no information
  double condition = 0.0;       // smallest / largest eigenvalue of the scaled normal matrix
  double rms_residual = 0.0;    // metres, last iteration
  // The pose's information (body-frame perturbation, (rho, phi)) from the
  // last iteration's normal equations over the residuals' own variance
  // (Censi's J^T J / sigma^2 at the optimum); degenerate directions carry none.
  Matrix6d information = Matrix6d::Zero();
};

// source: feature points in the LiDAR frame; threshold: largest
// correspondence distance (metres), the robust kernel is a third of it.
IcpResult registerMultiMetric(const std::vector<FeaturePoint>& source, const LocalMap& map,
                              const Eigen::Isometry3d& T_world_lidar_guess, double threshold,
                              const RegistrationConfig& config);

// Linear system of one Gauss-Newton step, public for tests.
struct NormalEquations {
  Matrix6d H = Matrix6d::Zero();
  Vector6d b = Vector6d::Zero();
  double squared_error = 0.0;  // of the residuals, each weighed by its return's noise
  std::size_t count = 0;
};

// The update (body-frame perturbation T <- T exp(x), (rho, phi)) that solves H x = -b in the
// well-conditioned directions only (Zhang et al., ICRA 2016, solution
// remapping); `degenerate` tells whether any direction was left out.
Vector6d solveWellConditioned(const NormalEquations& eq, double degeneracy_ratio, bool& degenerate,
                              double& condition);

// H / sigma^2 restricted to the directions solveWellConditioned uses (the
// others get no information), sigma^2 the noise-weighted mean squared
// residual (the variance of a return of weight 1).
Matrix6d wellConditionedInformation(const NormalEquations& eq, double degeneracy_ratio);

}  // namespace lvslam::lidar
