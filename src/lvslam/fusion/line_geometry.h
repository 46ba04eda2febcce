#pragma once
// Planes, 3D lines and direction clusters for fusion-line reconstruction.
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace lvslam::fusion {

// Plane n.x + d = 0 with unit normal n.
struct Plane {
  Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
  double d = 0.0;
  double signedDistance(const Eigen::Vector3d& x) const { return n.dot(x) + d; }
};

// Infinite line through `point` along unit `direction`.
struct Line3 {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
};

// Plane through the camera centre containing the rays a and b: the
// back-projected plane of an image segment (paper, plane-to-plane case).
std::optional<Plane> backProjectedPlane(const Eigen::Vector3d& ray_a, const Eigen::Vector3d& ray_b);

// Plane from LiDAR points with their normals: normal = the sign-aligned mean
// of the normals, offset = median of -n.p (robust to a few stray points).
std::optional<Plane> fitPlaneFromNormals(const std::vector<Eigen::Vector3d>& points,
                                         const std::vector<Eigen::Vector3d>& normals);

// Intersection of two planes; none when they are parallel within min_angle.
std::optional<Line3> intersectPlanes(const Plane& a, const Plane& b, double min_angle);

// Where the ray from the origin along `ray` meets the plane (positive depth only).
std::optional<Eigen::Vector3d> intersectRayPlane(const Eigen::Vector3d& ray, const Plane& plane);

// Point on the line closest to the ray from the origin along `ray` (the
// common perpendicular's foot on the line); none when they are parallel.
std::optional<Eigen::Vector3d> closestPointOnLineToRay(const Line3& line, const Eigen::Vector3d& ray);

// Greedy clustering of sign-less directions: the largest set of directions
// within max_angle of a seed direction; returns member indices and their
// mean direction (principal eigenvector of sum d d^T), L_best of the paper.
struct DirectionCluster {
  std::vector<std::size_t> members;
  Eigen::Vector3d mean_direction = Eigen::Vector3d::UnitX();
};
DirectionCluster dominantDirectionCluster(const std::vector<Eigen::Vector3d>& directions, double max_angle);

// Principal axis of sign-less unit directions (eigenvector of the largest
// eigenvalue of sum d d^T); a direction and its negation count the same.
Eigen::Vector3d meanAxis(const std::vector<Eigen::Vector3d>& directions);

}  // namespace lvslam::fusion
