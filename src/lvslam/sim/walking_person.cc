#include "lvslam/sim/walking_person.h"

#include <cmath>

#include "lvslam/sim/scene_builder.h"

namespace lvslam::sim {

Primitive WalkingPerson::at(double t) const {
  const Eigen::Vector2d d = to - from;
  const double length = d.norm();
  const double s = std::fmod(std::max(t, 0.0) * speed, 2.0 * length);
  const bool returning = s > length;
  const Eigen::Vector2d xy = from + d * ((returning ? 2.0 * length - s : s) / length);
  const double yaw = std::atan2(d.y(), d.x()) + (returning ? M_PI : 0.0);
  Primitive p;
  p.kind = PrimitiveKind::kBox;
  // Facing the walking direction: the box's width is across it.
  p.R = yawRotation(yaw + M_PI / 2);
  p.center = Eigen::Vector3d(xy.x(), xy.y(), 0.5 * size.z());
  p.half = 0.5 * size;
  p.texture = texture;
  return p;
}

void addPersonHit(const World& world, const WalkingPerson& person, double t, const Eigen::Vector3d& origin,
                  const Eigen::Vector3d& unit_dir, double max_range, double pixel_angle,
                  std::optional<WorldHit>& hit) {
  const double t_max = hit ? hit->distance : max_range;
  if (auto person_hit = world.raycastPrimitive(person.at(t), origin, unit_dir, t_max, pixel_angle))
    hit = person_hit;
}

}  // namespace lvslam::sim
