#include "lvslam/lidar/multi_metric_icp.h"

#include <cmath>

#include <Eigen/Eigenvalues>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

namespace lvslam::lidar {

namespace {

// Rotation columns of the Jacobian grow with range; this length (metres)
// makes translation and rotation comparable before judging degeneracy.
constexpr double kRotationScale = 10.0;

NormalEquations& operator+=(NormalEquations& a, const NormalEquations& b) {
  a.H += b.H;
  a.b += b.b;
  a.squared_error += b.squared_error;
  a.count += b.count;
  return a;
}

// Adds one residual r = A (q - m) with A = n^T (plane), I - d d^T (line) or
// I (point); dq = d q / d xi for q = T exp(xi) p (body-frame perturbation, so
// the rotation columns scale with the range, not with the distance travelled).
template <int Rows>
void addResidual(NormalEquations& eq, const Eigen::Matrix<double, Rows, 3>& A, const Eigen::Vector3d& q,
                 const Eigen::Matrix<double, 3, 6>& dq, const Eigen::Vector3d& m, double kernel,
                 double weight, double noise_weight) {
  const Eigen::Matrix<double, Rows, 1> r = A * (q - m);
  const Eigen::Matrix<double, Rows, 6> J = A * dq;
  // Geman-McClure weight, (k^2 / (k^2 + r^2))^2 (MULLS; kiss-icp's differs, k^2 / (k + r^2)^2).
  const double r_sq = r.squaredNorm();
  const double k_sq = kernel * kernel;
  const double w = weight * (k_sq / (k_sq + r_sq)) * (k_sq / (k_sq + r_sq));
  eq.H.noalias() += w * J.transpose() * J;
  eq.b.noalias() += w * J.transpose() * r;
  eq.squared_error += noise_weight * r_sq;  // the variance of a return of weight 1 (weighted least squares)
  ++eq.count;
}

// A return's position noise relative to the best one's: range noise plus the
// spread of where in the footprint the echo came from (a disk of radius
// r theta / 2, whose points have a standard deviation of r theta / 4 per axis).
double footprintWeight(const Eigen::Vector3d& p_sensor, const RegistrationConfig& config) {
  const double s0 = config.range_sigma * config.range_sigma;
  const double spread = p_sensor.norm() * config.beam_divergence / 4.0;
  return s0 / (s0 + spread * spread);
}

// Nearest map point of the same class within the threshold, or nullptr.
const MapPoint* associate(const FeaturePoint& fp, const Eigen::Isometry3d& T, const LocalMap& map, float threshold,
                          const RegistrationConfig& config) {
  if (fp.cls == FeatureClass::kBeam && config.beam_weight <= 0.0) return nullptr;
  return map.nearest((T * fp.p.cast<double>()).cast<float>(), fp.cls, threshold);
}

void addCorrespondence(NormalEquations& eq, const FeaturePoint& fp, const MapPoint* m, const Eigen::Isometry3d& T,
                       float threshold, double kernel, double min_cos, const RegistrationConfig& config) {
  if (m == nullptr) return;
  const Eigen::Vector3d p = fp.p.cast<double>();
  const Eigen::Vector3d q = T * p;
  const Eigen::Vector3d mp = m->p.cast<double>();
  // A kept association must still be within reach.
  if ((q - mp).squaredNorm() > static_cast<double>(threshold) * threshold) return;
  // Points across an edge share a class but not a surface: their directions disagree.
  const Eigen::Vector3d source_direction = T.linear() * fp.direction.cast<double>();
  if (fp.cls != FeatureClass::kVertex && std::abs(source_direction.dot(m->direction.cast<double>())) < min_cos) return;
  Eigen::Matrix<double, 3, 6> dq;
  dq << T.linear(), -T.linear() * skew(p);
  const double noise_weight = footprintWeight(p, config);
  if (isPlanar(fp.cls)) {
    addResidual<1>(eq, m->direction.cast<double>().transpose(), q, dq, mp, kernel, noise_weight, noise_weight);
  } else if (isLinear(fp.cls)) {
    // A fusion-refined direction (paper: d_v_mean) is preferred to a raw PCA one.
    const bool use_source = fp.refined && !m->refined;
    const Eigen::Vector3d d = use_source ? source_direction : Eigen::Vector3d(m->direction.cast<double>());
    const Eigen::Matrix3d A = Eigen::Matrix3d::Identity() - d * d.transpose();
    addResidual<3>(eq, A, q, dq, mp, kernel,
                   noise_weight * (fp.cls == FeatureClass::kBeam ? config.beam_weight : 1.0), noise_weight);
  } else {
    addResidual<3>(eq, Eigen::Matrix3d::Identity(), q, dq, mp, kernel, noise_weight * config.vertex_weight,
                   noise_weight);
  }
}

void associateAll(const std::vector<FeaturePoint>& source, const LocalMap& map, const Eigen::Isometry3d& T,
                  double threshold, const RegistrationConfig& config, std::vector<const MapPoint*>& matches) {
  matches.resize(source.size());
  const auto th = static_cast<float>(threshold);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, source.size(), 128),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i)
                        matches[i] = associate(source[i], T, map, th, config);
                    });
}

NormalEquations buildNormalEquations(const std::vector<FeaturePoint>& source,
                                     const std::vector<const MapPoint*>& matches, const Eigen::Isometry3d& T,
                                     double threshold, const RegistrationConfig& config) {
  const double kernel = threshold / 3.0;
  const auto th = static_cast<float>(threshold);
  const double min_cos = std::cos(config.max_normal_angle_deg * M_PI / 180.0);
  return tbb::parallel_deterministic_reduce(
      tbb::blocked_range<std::size_t>(0, source.size(), 128), NormalEquations{},
      [&](const tbb::blocked_range<std::size_t>& range, NormalEquations eq) {
        for (std::size_t i = range.begin(); i != range.end(); ++i)
          addCorrespondence(eq, source[i], matches[i], T, th, kernel, min_cos, config);
        return eq;
      },
      [](NormalEquations a, const NormalEquations& b) { return a += b; });
}

// How far the pose moved since the last association, as the displacement of
// a point kRotationScale metres away.
double motionBetween(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  const Eigen::Isometry3d delta = a.inverse() * b;
  return delta.translation().norm() + kRotationScale * rotationAngle(delta);
}

// The scaled normal matrix's eigen decomposition (ascending), with the
// indices of the directions that carry information.
struct ScaledEigen {
  Vector6d scale;
  Eigen::SelfAdjointEigenSolver<Matrix6d> solver;
  double condition = 0.0;
  bool degenerate = false;
  double ratio = 0.0;
  bool usable(int i) const { return !(solver.eigenvalues()(i) < ratio * solver.eigenvalues()(5)); }
  // Some direction carries information at all.
  bool informative() const {
    const double largest = solver.eigenvalues()(5);
    return largest > 0 && std::isfinite(largest);
  }
};

ScaledEigen scaledEigen(const Matrix6d& H_raw, double degeneracy_ratio) {
  ScaledEigen e;
  e.scale << 1, 1, 1, 1.0 / kRotationScale, 1.0 / kRotationScale, 1.0 / kRotationScale;
  e.ratio = degeneracy_ratio;
  e.solver.compute(e.scale.asDiagonal() * H_raw * e.scale.asDiagonal());
  const Vector6d lambda = e.solver.eigenvalues();
  const double largest = lambda(5);
  e.condition = largest > 0 ? lambda(0) / largest : 0.0;
  e.degenerate = !e.informative();
  for (int i = 0; i < 6 && !e.degenerate; ++i) e.degenerate = !e.usable(i);
  return e;
}

}  // namespace

Vector6d solveWellConditioned(const NormalEquations& eq, double degeneracy_ratio, bool& degenerate,
                              double& condition) {
  const ScaledEigen e = scaledEigen(eq.H, degeneracy_ratio);
  degenerate = e.degenerate;
  condition = e.condition;
  if (!e.informative()) return Vector6d::Zero();
  const Vector6d b = e.scale.asDiagonal() * eq.b;
  Vector6d x_scaled = Vector6d::Zero();
  for (int i = 0; i < 6; ++i) {
    if (!e.usable(i)) continue;
    const Vector6d v = e.solver.eigenvectors().col(i);
    x_scaled -= v * (v.dot(b) / e.solver.eigenvalues()(i));
  }
  return e.scale.asDiagonal() * x_scaled;
}

Matrix6d wellConditionedInformation(const NormalEquations& eq, double degeneracy_ratio) {
  if (eq.count == 0 || !(eq.squared_error > 0)) return Matrix6d::Zero();
  const ScaledEigen e = scaledEigen(eq.H, degeneracy_ratio);
  if (!e.informative()) return Matrix6d::Zero();
  Matrix6d H_scaled = Matrix6d::Zero();
  for (int i = 0; i < 6; ++i) {
    if (!e.usable(i)) continue;
    const Vector6d v = e.solver.eigenvectors().col(i);
    H_scaled += e.solver.eigenvalues()(i) * v * v.transpose();
  }
  // Undo the scaling (H = S^-1 H_scaled S^-1) and weigh by the residuals' own variance.
  const Vector6d inverse_scale = e.scale.cwiseInverse();
  const double variance = eq.squared_error / static_cast<double>(eq.count);
  return inverse_scale.asDiagonal() * H_scaled * inverse_scale.asDiagonal() / variance;
}

IcpResult registerMultiMetric(const std::vector<FeaturePoint>& source, const LocalMap& map,
                              const Eigen::Isometry3d& T_world_lidar_guess, double threshold,
                              const RegistrationConfig& config) {
  IcpResult result;
  result.T_world_lidar = T_world_lidar_guess;
  std::vector<const MapPoint*> matches;
  Eigen::Isometry3d T_associated = T_world_lidar_guess;
  NormalEquations eq;  // of the last iteration: the pose's information comes from it
  for (int iteration = 0; iteration < config.max_iterations; ++iteration) {
    // Near convergence the nearest neighbours no longer change: keep them
    // while the pose moved less than reassociate_motion (LOAM-style).
    if (iteration == 0 || motionBetween(T_associated, result.T_world_lidar) > config.reassociate_motion) {
      associateAll(source, map, result.T_world_lidar, threshold, config, matches);
      T_associated = result.T_world_lidar;
    }
    eq = buildNormalEquations(source, matches, result.T_world_lidar, threshold, config);
    result.iterations = iteration + 1;
    result.correspondences = eq.count;
    result.rms_residual = eq.count > 0 ? std::sqrt(eq.squared_error / eq.count) : 0.0;
    if (eq.count < config.min_correspondences) break;
    const Vector6d dx = solveWellConditioned(eq, config.degeneracy_ratio, result.degenerate, result.condition);
    result.T_world_lidar = result.T_world_lidar * expSE3(dx);
    if (dx.head<3>().norm() < config.converged_translation && dx.tail<3>().norm() < config.converged_rotation) {
      result.converged = true;
      break;
    }
  }
  result.information = wellConditionedInformation(eq, config.degeneracy_ratio);
  return result;
}

}  // namespace lvslam::lidar
