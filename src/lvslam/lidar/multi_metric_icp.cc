#include "lvslam/lidar/multi_metric_icp.h"

#include <algorithm>
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

// Pseudo-residuals of the pooled variance in each class's variance.
constexpr double kVariancePriorCount = 10.0;

// Linear system of one Gauss-Newton step, with each feature class's share
// (its residuals have a variance of their own: point-to-point residuals of
// scattered vertices are tens of times those of point-to-plane ones).
struct ClassEquations {
  Matrix6d H = Matrix6d::Zero();
  double squared_error = 0.0;
  std::size_t count = 0;
  ClassEquations& operator+=(const ClassEquations& o) {
    H += o.H;
    squared_error += o.squared_error;
    count += o.count;
    return *this;
  }
};

struct NormalEquations {
  Matrix6d H = Matrix6d::Zero();
  Vector6d b = Vector6d::Zero();
  double squared_error = 0.0;  // of the residuals, each weighed by its return's noise
  std::size_t count = 0;
  std::array<ClassEquations, kFeatureClassCount> classes;
};

// Which principal directions of the class-weighted information (rotation
// scaled by 10 m to compare with translation) the registration can see.
struct Localizability {
  Matrix6d directions = Matrix6d::Identity();  // columns, ascending eigenvalue
  // Information along each direction from the rows aligned with it, times the
  // robust kernel's width squared: at least 1 when the scan fixes it to
  // within the kernel.
  Vector6d seen = Vector6d::Zero();
  // The same rows' information with weight only (no class variance).
  Vector6d aligned_weight = Vector6d::Zero();
  std::array<bool, 6> usable{};
  bool degenerate() const;
  Eigen::Matrix<double, 6, Eigen::Dynamic> usableBasis() const;
};

NormalEquations& operator+=(NormalEquations& a, const NormalEquations& b) {
  a.H += b.H;
  a.b += b.b;
  a.squared_error += b.squared_error;
  a.count += b.count;
  for (int c = 0; c < kFeatureClassCount; ++c) a.classes[c] += b.classes[c];
  return a;
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

// Unit vectors spanning the plane orthogonal to d.
Eigen::Matrix<double, 2, 3> orthogonalBasis(const Eigen::Vector3d& d) {
  const Eigen::Vector3d a = std::abs(d.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e1 = d.cross(a).normalized();
  Eigen::Matrix<double, 2, 3> basis;
  basis << e1.transpose(), d.cross(e1).transpose();
  return basis;
}

// The residual rows of one kept correspondence, r = A (q - m) with A = n^T
// (plane), a basis orthogonal to d (line) or I (point), and J = A dq for
// q = T exp(xi) p (body-frame perturbation, so the rotation columns scale
// with the range, not with the distance travelled).
struct Correspondence {
  int rows = 0;
  Eigen::Matrix<double, 3, 6> J;
  Eigen::Vector3d r;
  double weight = 0.0;        // robust kernel x return noise x class weight
  double noise_weight = 0.0;  // return noise only: the variance of a return of weight 1
  FeatureClass cls = FeatureClass::kVertex;
};

bool makeCorrespondence(const FeaturePoint& fp, const MapPoint* m, const Eigen::Isometry3d& T, float threshold,
                        double kernel, double min_cos, const RegistrationConfig& config, Correspondence& c) {
  if (m == nullptr) return false;
  const Eigen::Vector3d p = fp.p.cast<double>();
  const Eigen::Vector3d q = T * p;
  const Eigen::Vector3d mp = m->p.cast<double>();
  // A kept association must still be within reach.
  if ((q - mp).squaredNorm() > static_cast<double>(threshold) * threshold) return false;
  // Points across an edge share a class but not a surface: their directions disagree.
  const Eigen::Vector3d source_direction = T.linear() * fp.direction.cast<double>();
  if (fp.cls != FeatureClass::kVertex && std::abs(source_direction.dot(m->direction.cast<double>())) < min_cos)
    return false;
  Eigen::Matrix<double, 3, 6> dq;
  dq << T.linear(), -T.linear() * skew(p);
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  double class_weight = 1.0;
  if (isPlanar(fp.cls)) {
    c.rows = 1;
    A.row(0) = m->direction.cast<double>().transpose();
  } else if (isLinear(fp.cls)) {
    // A fusion-refined direction (paper: d_v_mean) is preferred to a raw PCA one.
    const bool use_source = fp.refined && !m->refined;
    const Eigen::Vector3d d = use_source ? source_direction : Eigen::Vector3d(m->direction.cast<double>());
    c.rows = 2;
    A.topRows<2>() = orthogonalBasis(d);
    if (fp.cls == FeatureClass::kBeam) class_weight = config.beam_weight;
  } else {
    c.rows = 3;
    A.setIdentity();
    class_weight = config.vertex_weight;
  }
  c.J = A * dq;
  c.r = A * (q - mp);
  c.cls = fp.cls;
  c.noise_weight = footprintWeight(p, config);
  // Geman-McClure weight, (k^2 / (k^2 + r^2))^2 (MULLS; kiss-icp's differs, k^2 / (k + r^2)^2).
  const double k_sq = kernel * kernel;
  const double robust = k_sq / (k_sq + c.r.squaredNorm());
  c.weight = class_weight * c.noise_weight * robust * robust;
  return true;
}

// Adds one correspondence to the normal equations, overall and of its class.
void addCorrespondence(NormalEquations& eq, const Correspondence& c) {
  const auto J = c.J.topRows(c.rows);
  const auto r = c.r.head(c.rows);
  const Matrix6d H = c.weight * J.transpose() * J;
  eq.H += H;
  eq.b.noalias() += c.weight * J.transpose() * r;
  const double squared_error = c.noise_weight * r.squaredNorm();  // weighted least squares
  eq.squared_error += squared_error;
  ++eq.count;
  ClassEquations& cls = eq.classes[static_cast<int>(c.cls)];
  cls.H += H;
  cls.squared_error += squared_error;
  ++cls.count;
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

// The correspondences of one iteration, for the normal equations and the
// localizability test.
struct Correspondences {
  const std::vector<FeaturePoint>& source;
  const std::vector<const MapPoint*>& matches;
  const Eigen::Isometry3d& T;
  double threshold;
  const RegistrationConfig& config;

  // Folds f(Correspondence, Accumulator&) over the kept correspondences, in
  // a fixed order (deterministic sums).
  template <typename Accumulator, typename Add>
  Accumulator reduce(Add add) const {
    const double kernel = threshold / 3.0;
    const auto th = static_cast<float>(threshold);
    const double min_cos = std::cos(config.max_normal_angle_deg * M_PI / 180.0);
    return tbb::parallel_deterministic_reduce(
        tbb::blocked_range<std::size_t>(0, source.size(), 128), Accumulator{},
        [&](const tbb::blocked_range<std::size_t>& range, Accumulator acc) {
          Correspondence c;
          for (std::size_t i = range.begin(); i != range.end(); ++i)
            if (makeCorrespondence(source[i], matches[i], T, th, kernel, min_cos, config, c)) add(c, acc);
          return acc;
        },
        [](Accumulator a, const Accumulator& b) { return a += b; });
  }
};

// How far the pose moved since the last association, as the displacement of
// a point kRotationScale metres away.
double motionBetween(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  const Eigen::Isometry3d delta = a.inverse() * b;
  return delta.translation().norm() + kRotationScale * rotationAngle(delta);
}

const Vector6d& rotationScaling() {
  static const Vector6d scale = (Vector6d() << 1, 1, 1, 1 / kRotationScale, 1 / kRotationScale, 1 / kRotationScale)
                                    .finished();
  return scale;
}

// Information along each principal direction from the rows aligned with it.
struct DirectionSums {
  Vector6d aligned = Vector6d::Zero();
  Vector6d aligned_weight = Vector6d::Zero();
  DirectionSums& operator+=(const DirectionSums& o) {
    aligned += o.aligned;
    aligned_weight += o.aligned_weight;
    return *this;
  }
};

// Each class's residual variance (of a return of weight 1), shrunk toward
// the pooled one by a few pseudo-residuals, and at least `floor`.
std::array<double, kFeatureClassCount> classVariances(const NormalEquations& eq, double floor) {
  std::array<double, kFeatureClassCount> variance{};
  const double pooled = eq.count > 0 ? eq.squared_error / static_cast<double>(eq.count) : 0.0;
  for (int c = 0; c < kFeatureClassCount; ++c) {
    const ClassEquations& cls = eq.classes[c];
    // Shrunk toward the pooled variance, so that a class of a handful of
    // residuals does not claim a variance of its own.
    variance[c] = std::max(floor, (cls.squared_error + kVariancePriorCount * pooled) /
                                      (static_cast<double>(cls.count) + kVariancePriorCount));
  }
  return variance;
}

// Censi's information J^T J / sigma^2, each class's share over its own variance.
Matrix6d classWeightedInformation(const NormalEquations& eq, const std::array<double, kFeatureClassCount>& variance) {
  Matrix6d information = Matrix6d::Zero();
  for (int c = 0; c < kFeatureClassCount; ++c)
    if (eq.classes[c].count > 0 && variance[c] > 0) information += eq.classes[c].H / variance[c];
  return information;
}

Eigen::Matrix<double, 6, Eigen::Dynamic> Localizability::usableBasis() const {
  Eigen::Matrix<double, 6, Eigen::Dynamic> basis(6, 0);
  for (int i = 0; i < 6; ++i) {
    if (!usable[i]) continue;
    basis.conservativeResize(Eigen::NoChange, basis.cols() + 1);
    basis.col(basis.cols() - 1) = directions.col(i);
  }
  return basis;
}

bool Localizability::degenerate() const {
  for (const bool u : usable)
    if (!u) return true;
  return false;
}

// The update (body-frame perturbation T <- T exp(x), (rho, phi)) solving
// H x = -b within the usable directions; the others stay at the guess
// (solution remapping, Zhang et al., ICRA 2016).
Vector6d solveInSubspace(const NormalEquations& eq, const Localizability& loc) {
  const Vector6d& s = rotationScaling();
  const Eigen::Matrix<double, 6, Eigen::Dynamic> U = loc.usableBasis();
  if (U.cols() == 0) return Vector6d::Zero();
  const Matrix6d H = s.asDiagonal() * eq.H * s.asDiagonal();
  const Vector6d b = s.asDiagonal() * eq.b;
  const Eigen::MatrixXd reduced = U.transpose() * H * U;
  const Eigen::VectorXd y = reduced.ldlt().solve(-(U.transpose() * b));
  return s.asDiagonal() * (U * y);
}

Matrix6d usableInformation(const NormalEquations& eq, const Localizability& loc) {
  if (eq.count == 0 || !(eq.squared_error > 0)) return Matrix6d::Zero();
  // Along each seen direction, the information of the rows aligned with it
  // over the pooled variance (what the estimator's weights were measured
  // with): the rows nearly orthogonal to it carry their normals' noise.
  const Vector6d& s = rotationScaling();
  const double variance = eq.squared_error / static_cast<double>(eq.count);
  Matrix6d scaled = Matrix6d::Zero();
  for (int i = 0; i < 6; ++i)
    if (loc.usable[i])
      scaled += loc.directions.col(i) * loc.directions.col(i).transpose() * (loc.aligned_weight(i) / variance);
  const Vector6d inverse = s.cwiseInverse();
  return inverse.asDiagonal() * scaled * inverse.asDiagonal();
}

// X-ICP's localizability (Tuna et al., T-RO 2023, Sec. IV): along each
// principal direction of the information only residual rows aligned with it
// count; the many rows nearly orthogonal to it (a corridor's walls along its
// axis) add up to an eigenvalue made of their normals' noise, not geometry.
// A direction is seen when that information fixes it to within the robust
// kernel's width: less, and every offset along it fits the kept
// correspondences alike.
Localizability analyseLocalizability(const Correspondences& corr, const NormalEquations& eq) {
  Localizability loc;
  const Vector6d& s = rotationScaling();
  // No residual is more precise than the sensor (noise-free data fits exactly).
  const auto variance = classVariances(eq, corr.config.range_sigma * corr.config.range_sigma);
  const Eigen::SelfAdjointEigenSolver<Matrix6d> solver(s.asDiagonal() * classWeightedInformation(eq, variance) *
                                                       s.asDiagonal());
  loc.directions = solver.eigenvectors();
  if (!solver.eigenvalues().allFinite()) return loc;  // nothing usable
  const double min_cos = std::cos(corr.config.localizability_angle_deg * M_PI / 180.0);
  const Matrix6d& V = loc.directions;
  const DirectionSums sums = corr.reduce<DirectionSums>([&](const Correspondence& c, DirectionSums& acc) {
    const double v = variance[static_cast<int>(c.cls)];
    if (!(v > 0)) return;
    for (int row = 0; row < c.rows; ++row) {
      const Eigen::Matrix<double, 1, 6> J = c.J.row(row) * s.asDiagonal();
      const double norm = J.norm();
      if (!(norm > 0)) continue;
      const Eigen::Matrix<double, 1, 6> along = J * V;
      for (int i = 0; i < 6; ++i)
        if (std::abs(along(i)) >= min_cos * norm) {
          acc.aligned(i) += c.weight * along(i) * along(i) / v;
          acc.aligned_weight(i) += c.weight * along(i) * along(i);
        }
    }
  });
  const double kernel = corr.threshold / 3.0;
  loc.seen = sums.aligned * kernel * kernel;
  loc.aligned_weight = sums.aligned_weight;
  for (int i = 0; i < 6; ++i) loc.usable[i] = loc.seen(i) >= 1.0;
  return loc;
}

}  // namespace

IcpResult registerMultiMetric(const std::vector<FeaturePoint>& source, const LocalMap& map,
                              const Eigen::Isometry3d& T_world_lidar_guess, double threshold,
                              const RegistrationConfig& config) {
  IcpResult result;
  result.T_world_lidar = T_world_lidar_guess;
  std::vector<const MapPoint*> matches;
  Eigen::Isometry3d T_associated = T_world_lidar_guess;
  NormalEquations eq;  // of the last iteration: the pose's information comes from it
  Localizability loc;
  for (int iteration = 0; iteration < config.max_iterations; ++iteration) {
    // Near convergence the nearest neighbours no longer change: keep them
    // while the pose moved less than reassociate_motion (LOAM-style).
    if (iteration == 0 || motionBetween(T_associated, result.T_world_lidar) > config.reassociate_motion) {
      associateAll(source, map, result.T_world_lidar, threshold, config, matches);
      T_associated = result.T_world_lidar;
    }
    const Correspondences corr{source, matches, result.T_world_lidar, threshold, config};
    eq = corr.reduce<NormalEquations>([](const Correspondence& c, NormalEquations& acc) { addCorrespondence(acc, c); });
    result.iterations = iteration + 1;
    result.correspondences = eq.count;
    result.rms_residual = eq.count > 0 ? std::sqrt(eq.squared_error / eq.count) : 0.0;
    if (eq.count < config.min_correspondences) break;
    loc = analyseLocalizability(corr, eq);
    result.degenerate = loc.degenerate();
    result.localizability = loc.seen.minCoeff();
    const Vector6d dx = solveInSubspace(eq, loc);
    result.T_world_lidar = result.T_world_lidar * expSE3(dx);
    if (dx.head<3>().norm() < config.converged_translation && dx.tail<3>().norm() < config.converged_rotation) {
      result.converged = true;
      break;
    }
  }
  result.information = usableInformation(eq, loc);
  return result;
}

}  // namespace lvslam::lidar
