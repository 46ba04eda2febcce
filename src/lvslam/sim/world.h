#pragma once
// The simulated world: analytic primitives with procedural textures. The
// exact truth for tests and other subsystems: ray casts, distances to the
// true surfaces and the true 3D line segments.
#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "lvslam/sim/bvh.h"
#include "lvslam/sim/primitive.h"
#include "lvslam/sim/texture.h"

namespace lvslam::sim {

struct WorldHit {
  double distance = 0.0;                             // along the unit ray, metres
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, facing the ray
  double albedo = 0.0;                               // reflectance at the hit, [0, 1]
  int primitive = -1;                                // index into primitives()
};

// A true straight 3D line segment of the geometry (box edge, frame edge,
// wall-floor or wall-ceiling boundary, pillar edge), in world coordinates.
struct WorldEdge {
  Eigen::Vector3d a, b;
  int primitive = -1;
};

class World {
 public:
  World() = default;
  // Every primitive's texture must index `textures`.
  World(std::vector<Primitive> primitives, std::vector<Texture> textures);

  const std::vector<Primitive>& primitives() const { return primitives_; }
  const std::vector<Texture>& textures() const { return textures_; }

  // Nearest surface along the ray from `origin` in direction `dir` (need not
  // be unit), up to max_range. `pixel_angle` (radians) is the angular size of
  // one pixel, used to filter textures; 0 for a point sample (LiDAR). Glass
  // panes are surfaces unless `through_glass`.
  std::optional<WorldHit> raycast(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                                  double max_range = 1e9, double pixel_angle = 0.0,
                                  bool through_glass = false) const;
  // Same, testing only the given primitives (a renderer's culled list).
  std::optional<WorldHit> raycastAmong(const std::vector<int>& ids, const Eigen::Vector3d& origin,
                                       const Eigen::Vector3d& unit_dir, double max_range,
                                       double pixel_angle) const;

  // A primitive that is not part of the world (a moving object), textured
  // with the world's textures; its hits carry primitive -1.
  std::optional<WorldHit> raycastPrimitive(const Primitive& primitive, const Eigen::Vector3d& origin,
                                           const Eigen::Vector3d& unit_dir, double max_range,
                                           double pixel_angle) const;

  // Distance of a point to the nearest analytic surface.
  double distanceToSurface(const Eigen::Vector3d& p) const;

  // All true straight edges of the geometry.
  std::vector<WorldEdge> edges() const;

 private:
  WorldHit shade(int id, const SurfaceHit& hit, const Eigen::Vector3d& unit_dir, double pixel_angle) const;
  WorldHit shadeWith(int texture, int id, const SurfaceHit& hit, const Eigen::Vector3d& unit_dir,
                     double pixel_angle) const;

  std::vector<Primitive> primitives_;
  std::vector<Texture> textures_;
  std::vector<AlignedBox> boxes_;
  Bvh bvh_;
};

}  // namespace lvslam::sim
