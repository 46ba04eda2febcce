#include "lvslam/fusion/line_geometry.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

namespace lvslam::fusion {

std::optional<Plane> backProjectedPlane(const Eigen::Vector3d& ray_a, const Eigen::Vector3d& ray_b) {
  const Eigen::Vector3d n = ray_a.cross(ray_b);
  const double norm = n.norm();
  if (!(norm > 1e-12 * ray_a.norm() * ray_b.norm())) return std::nullopt;
  return Plane{n / norm, 0.0};
}

std::optional<Plane> fitPlaneFromNormals(const std::vector<Eigen::Vector3d>& points,
                                         const std::vector<Eigen::Vector3d>& normals) {
  if (points.empty() || points.size() != normals.size()) return std::nullopt;
  const Eigen::Vector3d n = meanAxis(normals);
  std::vector<double> offsets;
  offsets.reserve(points.size());
  for (const auto& p : points) offsets.push_back(-n.dot(p));
  std::nth_element(offsets.begin(), offsets.begin() + offsets.size() / 2, offsets.end());
  return Plane{n, offsets[offsets.size() / 2]};
}

std::optional<Line3> intersectPlanes(const Plane& a, const Plane& b, double min_angle) {
  const Eigen::Vector3d dir = a.n.cross(b.n);
  const double s = dir.norm();
  if (!(s > std::sin(min_angle))) return std::nullopt;
  // The point of the line closest to the origin solves n_a.x = -d_a,
  // n_b.x = -d_b, dir.x = 0.
  Eigen::Matrix3d A;
  A.row(0) = a.n.transpose();
  A.row(1) = b.n.transpose();
  A.row(2) = dir.transpose();
  const Eigen::Vector3d rhs(-a.d, -b.d, 0.0);
  return Line3{A.colPivHouseholderQr().solve(rhs), dir / s};
}

std::optional<Eigen::Vector3d> intersectRayPlane(const Eigen::Vector3d& ray, const Plane& plane) {
  const double denom = plane.n.dot(ray);
  if (std::abs(denom) < 1e-12) return std::nullopt;
  const double s = -plane.d / denom;
  if (!(s > 0.0)) return std::nullopt;
  return Eigen::Vector3d(s * ray);
}

std::optional<Eigen::Vector3d> closestPointOnLineToRay(const Line3& line, const Eigen::Vector3d& ray) {
  // Minimise |line.point + s u - t r| over s, t (two lines' common perpendicular).
  const Eigen::Vector3d u = line.direction;
  const Eigen::Vector3d r = ray.normalized();
  const double b = u.dot(r);
  const double denom = 1.0 - b * b;
  if (denom < 1e-12) return std::nullopt;
  const Eigen::Vector3d w = line.point;
  const double s = (b * r.dot(w) - u.dot(w)) / denom;
  return Eigen::Vector3d(line.point + s * u);
}

Eigen::Vector3d meanAxis(const std::vector<Eigen::Vector3d>& directions) {
  Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
  for (const auto& d : directions) S += d * d.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(S);
  Eigen::Vector3d axis = eig.eigenvectors().col(2);
  // Point it the way most inputs point, so it is a direction, not just an axis.
  double vote = 0.0;
  for (const auto& d : directions) vote += axis.dot(d);
  return vote < 0.0 ? Eigen::Vector3d(-axis) : axis;
}

DirectionCluster dominantDirectionCluster(const std::vector<Eigen::Vector3d>& directions, double max_angle) {
  DirectionCluster best;
  const double cos_max = std::cos(max_angle);
  for (std::size_t seed = 0; seed < directions.size(); ++seed) {
    std::vector<std::size_t> members;
    for (std::size_t j = 0; j < directions.size(); ++j)
      if (std::abs(directions[seed].dot(directions[j])) >= cos_max) members.push_back(j);
    if (members.size() > best.members.size()) best.members = std::move(members);
  }
  std::vector<Eigen::Vector3d> member_dirs;
  for (const std::size_t i : best.members) member_dirs.push_back(directions[i]);
  if (!member_dirs.empty()) best.mean_direction = meanAxis(member_dirs);
  return best;
}

}  // namespace lvslam::fusion
