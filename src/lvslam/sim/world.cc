#include "lvslam/sim/world.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "lvslam/core/error.h"

namespace lvslam::sim {

World::World(std::vector<Primitive> primitives, std::vector<Texture> textures)
    : primitives_(std::move(primitives)), textures_(std::move(textures)) {
  for (std::size_t i = 0; i < primitives_.size(); ++i) {
    const int t = primitives_[i].texture;
    if (t < 0 || t >= static_cast<int>(textures_.size()))
      throw Error("sim::World", fmt::format("primitive {} has texture {} of {}", i, t, textures_.size()));
    boxes_.push_back(bounds(primitives_[i]));
  }
  bvh_ = Bvh(boxes_);
}

WorldHit World::shade(int id, const SurfaceHit& hit, const Eigen::Vector3d& unit_dir, double pixel_angle) const {
  return shadeWith(primitives_[id].texture, id, hit, unit_dir, pixel_angle);
}

WorldHit World::shadeWith(int texture, int id, const SurfaceHit& hit, const Eigen::Vector3d& unit_dir,
                          double pixel_angle) const {
  // A pixel's footprint grows with distance and with grazing incidence.
  const double cos_incidence = std::max(std::abs(hit.normal.dot(unit_dir)), 0.1);
  const double footprint = hit.distance * pixel_angle / cos_incidence;
  return WorldHit{hit.distance, hit.normal, albedoAt(textures_[texture], hit.uv, footprint), id};
}

std::optional<WorldHit> World::raycastPrimitive(const Primitive& primitive, const Eigen::Vector3d& origin,
                                                const Eigen::Vector3d& unit_dir, double max_range,
                                                double pixel_angle) const {
  if (primitive.texture < 0 || primitive.texture >= static_cast<int>(textures_.size())) return std::nullopt;
  const auto hit = intersect(primitive, origin, unit_dir, max_range);
  if (!hit) return std::nullopt;
  return shadeWith(primitive.texture, -1, *hit, unit_dir, pixel_angle);
}

std::optional<WorldHit> World::raycast(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double max_range,
                                       double pixel_angle, bool through_glass) const {
  const double norm = dir.norm();
  if (!(norm > 0.0) || !origin.allFinite()) return std::nullopt;
  const Eigen::Vector3d d = dir / norm;
  double t_max = max_range;
  std::optional<SurfaceHit> best;
  int best_id = -1;
  bvh_.traverse(origin, d, t_max, [&](int id) {
    if (through_glass && primitives_[id].glass) return;
    if (auto hit = intersect(primitives_[id], origin, d, t_max)) {
      t_max = hit->distance;
      best = hit;
      best_id = id;
    }
  });
  if (!best) return std::nullopt;
  return shade(best_id, *best, d, pixel_angle);
}

std::optional<WorldHit> World::raycastAmong(const std::vector<int>& ids, const Eigen::Vector3d& origin,
                                            const Eigen::Vector3d& unit_dir, double max_range,
                                            double pixel_angle) const {
  double t_max = max_range;
  std::optional<SurfaceHit> best;
  int best_id = -1;
  for (const int id : ids) {
    if (auto hit = intersect(primitives_[id], origin, unit_dir, t_max)) {
      t_max = hit->distance;
      best = hit;
      best_id = id;
    }
  }
  if (!best) return std::nullopt;
  return shade(best_id, *best, unit_dir, pixel_angle);
}

double World::distanceToSurface(const Eigen::Vector3d& p) const {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < primitives_.size(); ++i) {
    if (boxes_[i].distanceTo(p) >= best) continue;  // the surface lies inside its box
    best = std::min(best, sim::distanceToSurface(primitives_[i], p));
  }
  return best;
}

std::vector<WorldEdge> World::edges() const {
  std::vector<WorldEdge> result;
  for (std::size_t i = 0; i < primitives_.size(); ++i)
    for (const auto& e : straightEdges(primitives_[i])) result.push_back({e[0], e[1], static_cast<int>(i)});
  return result;
}

}  // namespace lvslam::sim
