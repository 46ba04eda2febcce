#include "lvslam/sim/walking_person.h"

#include <algorithm>
#include <cmath>

#include "lvslam/sim/counter_random.h"
#include "lvslam/sim/scene_builder.h"

namespace lvslam::sim {

Primitive WalkingPerson::at(double t) const {
  const Eigen::Vector2d d = to - from;
  const double length = d.norm();
  const double s = std::fmod(std::max(t, 0.0) * speed + phase, 2.0 * length);
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

std::vector<WalkingPerson> makePeople(const WalkingPerson& first, const std::vector<WalkingLane>& lanes, int count,
                                      const std::vector<int>& clothes, std::uint64_t seed) {
  std::vector<WalkingPerson> people;
  if (count <= 0) return people;
  people.push_back(first);
  CounterRandom rng(seed, RandomStream::kScene, 1);  // frame 1: the scene itself draws from frame 0
  for (int i = 1; i < count && !lanes.empty(); ++i) {
    const auto& [a, b] = lanes[(i - 1) % lanes.size()];
    WalkingPerson person = first;
    const double length = (b - a).norm();
    const double walk = std::min(length, rng.uniform(5.0, 15.0));
    const double start = rng.uniform(0.0, length - walk);
    const Eigen::Vector2d dir = (b - a) / length;
    person.from = a + start * dir;
    person.to = a + (start + walk) * dir;
    if (rng.uniform() < 0.5) std::swap(person.from, person.to);
    person.speed = rng.uniform(0.8, 1.5);
    person.phase = rng.uniform(0.0, 2.0 * walk);
    person.size.z() = rng.uniform(1.55, 1.9);
    person.texture = clothes[static_cast<std::size_t>(i) % clothes.size()];
    people.push_back(person);
  }
  return people;
}

std::vector<Primitive> peopleAt(const std::vector<WalkingPerson>& people, double t) {
  std::vector<Primitive> boxes;
  boxes.reserve(people.size());
  for (const WalkingPerson& person : people) boxes.push_back(person.at(t));
  return boxes;
}

void addPersonHit(const World& world, const Primitive& person_box, const Eigen::Vector3d& origin,
                  const Eigen::Vector3d& unit_dir, double max_range, double pixel_angle,
                  std::optional<WorldHit>& hit) {
  const double t_max = hit ? hit->distance : max_range;
  if (auto person_hit = world.raycastPrimitive(person_box, origin, unit_dir, t_max, pixel_angle))
    hit = person_hit;
}

}  // namespace lvslam::sim
