#pragma once
// Analytic surfaces of the simulated world: rectangles, boxes, cylinders and
// spheres, each a pose (local axes R, centre c) and half sizes. Exact ray
// intersection, distance to the surface, bounds and straight edges.
#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace lvslam::sim {

enum class PrimitiveKind {
  kRect,      // the local z = 0 rectangle |x| <= half.x, |y| <= half.y, two-sided
  kBox,       // |x|, |y|, |z| <= half
  kCylinder,  // closed cylinder about local z: radius half.x, |z| <= half.z
  kSphere,    // radius half.x
};

struct Primitive {
  PrimitiveKind kind = PrimitiveKind::kBox;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();  // columns: local axes in the world
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Vector3d half = Eigen::Vector3d::Zero();
  int texture = 0;  // index into World's textures
  // A glass pane: the camera sees through it, the LiDAR gets no return from
  // it (or one from behind it, lidar_beam.h).
  bool glass = false;
};

struct AlignedBox {
  Eigen::Vector3d min = Eigen::Vector3d::Constant(1e300);
  Eigen::Vector3d max = Eigen::Vector3d::Constant(-1e300);
  void extend(const Eigen::Vector3d& p) { min = min.cwiseMin(p); max = max.cwiseMax(p); }
  void extend(const AlignedBox& b) { min = min.cwiseMin(b.min); max = max.cwiseMax(b.max); }
  // Whether a ray (inverse direction given) enters the box before t_max.
  bool hitBy(const Eigen::Vector3d& origin, const Eigen::Vector3d& inv_dir, double t_max) const {
    return entryDistance(origin, inv_dir, t_max) <= t_max;
  }
  // Where the ray enters the box (0 from inside), or infinity when it misses
  // it before t_max.
  double entryDistance(const Eigen::Vector3d& origin, const Eigen::Vector3d& inv_dir, double t_max) const;
  double distanceTo(const Eigen::Vector3d& p) const;
};

// Where a ray meets a primitive: distance along the (unit) ray, the surface
// normal facing the ray, and surface coordinates in metres for texturing.
struct SurfaceHit {
  double distance = 0.0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
};

std::optional<SurfaceHit> intersect(const Primitive& p, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                                    double t_max);

// Unsigned distance of a point to the primitive's surface.
double distanceToSurface(const Primitive& p, const Eigen::Vector3d& point);

AlignedBox bounds(const Primitive& p);

// Corners of a convex polytope that encloses the primitive (4 for a rect, 8
// otherwise) and its edges as index pairs; used to cull by projection.
struct BoundingPolytope {
  std::vector<Eigen::Vector3d> corners;
  const std::vector<std::array<int, 2>>* edges = nullptr;
};
BoundingPolytope boundingPolytope(const Primitive& p);

// The primitive's true straight edges (rect border, box edges; none for
// curved surfaces).
std::vector<std::array<Eigen::Vector3d, 2>> straightEdges(const Primitive& p);

}  // namespace lvslam::sim
