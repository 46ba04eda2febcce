#pragma once
// People walking back and forth between two points, each an upright box that
// moves (people walk through M2DGR's rooms and halls). Not part of the static
// World: sensors add them at each ray's own time.
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "lvslam/sim/world.h"

namespace lvslam::sim {

struct WalkingPerson {
  Eigen::Vector2d from = Eigen::Vector2d::Zero(), to = Eigen::Vector2d::UnitX();
  double speed = 1.1;                            // m/s
  double phase = 0.0;                            // metres already walked (out and back) at t = 0
  Eigen::Vector3d size{0.5, 0.3, 1.75};          // shoulder width, depth, height
  int texture = 0;                               // index into the world's textures

  // The person's box at t seconds after the sequence start (a triangle wave
  // between `from` and `to`, facing the walking direction).
  Primitive at(double t) const;
};

// A straight stretch of floor where people may walk (clear of furniture).
using WalkingLane = std::pair<Eigen::Vector2d, Eigen::Vector2d>;

// `count` people: the first is `first`, the others walk on the lanes in turn,
// each between two points of its lane at least 5 m apart, at its own speed
// (0.8-1.5 m/s) and phase, dressed in one of `clothes`; all drawn from `seed`.
std::vector<WalkingPerson> makePeople(const WalkingPerson& first, const std::vector<WalkingLane>& lanes, int count,
                                      const std::vector<int>& clothes, std::uint64_t seed);

// Everyone's box at time t (sensors take them once per column or row).
std::vector<Primitive> peopleAt(const std::vector<WalkingPerson>& people, double t);

// The nearer of `hit` and the person's box along the ray (a person's hit
// carries primitive -1).
void addPersonHit(const World& world, const Primitive& person_box, const Eigen::Vector3d& origin,
                  const Eigen::Vector3d& unit_dir, double max_range, double pixel_angle,
                  std::optional<WorldHit>& hit);

}  // namespace lvslam::sim
