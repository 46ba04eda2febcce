#pragma once
// MULLS multi-metric ICP (Pan et al. 2021, Sec. III-C): class-wise nearest
// neighbours in the local map, point-to-plane residuals for ground / facade /
// roof, point-to-line for pillar / beam, point-to-point for vertex, robust
// weights, Gauss-Newton on SE3 with directions the scan cannot see (X-ICP's
// localizability) held at the guess.
#include <array>
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
  bool degenerate = false;      // some direction was not localizable (Localizability)
  double localizability = 0.0;  // the weakest direction's Localizability::seen, last iteration
  double rms_residual = 0.0;    // metres, last iteration
  // The pose's information (body-frame perturbation, (rho, phi)) from the
  // last iteration (classWeightedInformation); degenerate directions carry none.
  Matrix6d information = Matrix6d::Zero();
};

// source: feature points in the LiDAR frame; threshold: largest
// correspondence distance (metres), the robust kernel is a third of it.
IcpResult registerMultiMetric(const std::vector<FeaturePoint>& source, const LocalMap& map,
                              const Eigen::Isometry3d& T_world_lidar_guess, double threshold,
                              const RegistrationConfig& config);

// Linear system of one Gauss-Newton step, with each feature class's share
// (its residuals have a variance of their own: point-to-point residuals of
// scattered vertices are tens of times those of point-to-plane ones).
struct ClassEquations {
  Matrix6d H = Matrix6d::Zero();
  double squared_error = 0.0;
  std::size_t count = 0;
  ClassEquations& operator+=(const ClassEquations& o);
};

struct NormalEquations {
  Matrix6d H = Matrix6d::Zero();
  Vector6d b = Vector6d::Zero();
  double squared_error = 0.0;  // of the residuals, each weighed by its return's noise
  std::size_t count = 0;
  std::array<ClassEquations, kFeatureClassCount> classes;
};

// Each class's residual variance (of a return of weight 1), shrunk toward
// the pooled one by a few pseudo-residuals, and at least `floor`.
std::array<double, kFeatureClassCount> classVariances(const NormalEquations& eq, double floor);

// Censi's information J^T J / sigma^2 at the optimum, each class's share over
// its own variance (body-frame perturbation, (rho, phi)).
Matrix6d classWeightedInformation(const NormalEquations& eq, double floor);

// Which principal directions of the class-weighted information (rotation
// scaled by 10 m to compare with translation) the registration can see.
struct Localizability {
  Matrix6d directions = Matrix6d::Identity();  // columns, ascending eigenvalue
  Vector6d eigenvalues = Vector6d::Zero();
  // Information along each direction from the rows aligned with it, times the
  // robust kernel's width squared: at least 1 when the scan fixes it to
  // within the kernel.
  Vector6d seen = Vector6d::Zero();
  std::array<bool, 6> usable{};
  bool degenerate() const;
  Eigen::Matrix<double, 6, Eigen::Dynamic> usableBasis() const;
};

// The update (body-frame perturbation T <- T exp(x), (rho, phi)) solving
// H x = -b within the usable directions; the others stay at the guess
// (solution remapping, Zhang et al., ICRA 2016).
Vector6d solveInSubspace(const NormalEquations& eq, const Localizability& loc);

// Censi's J^T J / sigma^2 (sigma^2 the pooled variance of a return of
// weight 1) projected onto the usable directions.
Matrix6d usableInformation(const NormalEquations& eq, const Localizability& loc);

}  // namespace lvslam::lidar
