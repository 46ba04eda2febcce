#pragma once
// A person walking back and forth between two points, as an upright box
// that moves (people walk through M2DGR's rooms). Not part of the static
// World: sensors add it at each ray's own time.
#include <optional>

#include <Eigen/Core>

#include "lvslam/sim/world.h"

namespace lvslam::sim {

struct WalkingPerson {
  Eigen::Vector2d from = Eigen::Vector2d::Zero(), to = Eigen::Vector2d::UnitX();
  double speed = 1.1;                            // m/s
  Eigen::Vector3d size{0.5, 0.3, 1.75};          // shoulder width, depth, height
  int texture = 0;                               // index into the world's textures

  // The person's box at t seconds after the sequence start (a triangle wave
  // between `from` and `to`, facing the walking direction).
  Primitive at(double t) const;
};

// The nearer of `hit` and the person at time t along the ray.
void addPersonHit(const World& world, const WalkingPerson& person, double t, const Eigen::Vector3d& origin,
                  const Eigen::Vector3d& unit_dir, double max_range, double pixel_angle,
                  std::optional<WorldHit>& hit);

}  // namespace lvslam::sim
