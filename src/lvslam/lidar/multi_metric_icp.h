#pragma once
// MULLS multi-metric ICP (Pan et al. 2021, Sec. III-C): class-wise nearest
// neighbours in the local map, point-to-plane residuals for ground / facade /
// roof, point-to-line for pillar / beam, point-to-point for vertex, robust
// weights, Gauss-Newton on SE3 with directions the scan cannot see (X-ICP's
// localizability) held at the guess.
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
  bool degenerate = false;      // some direction was not seen (X-ICP's localizability)
  // The weakest principal direction's aligned information times the robust
  // kernel's width squared, last iteration: below 1 it was not seen.
  double localizability = 0.0;
  double rms_residual = 0.0;    // metres, last iteration
  // The pose's information (body-frame perturbation, (rho, phi)): along each
  // principal direction seen, Censi's J^T J / sigma^2 of the last
  // iteration's residual rows aligned with it (sigma^2 the pooled variance
  // of a return of weight 1); none along the others.
  Matrix6d information = Matrix6d::Zero();
};

// source: feature points in the LiDAR frame; threshold: largest
// correspondence distance (metres), the robust kernel is a third of it.
IcpResult registerMultiMetric(const std::vector<FeaturePoint>& source, const LocalMap& map,
                              const Eigen::Isometry3d& T_world_lidar_guess, double threshold,
                              const RegistrationConfig& config);

}  // namespace lvslam::lidar
