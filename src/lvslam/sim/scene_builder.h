#pragma once
// Collects primitives and textures while a scenario is assembled, with the
// seeded random source for its variations.
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/sim/counter_random.h"
#include "lvslam/sim/world.h"

namespace lvslam::sim {

// A vertical wall face: `origin` on the floor, `along` the wall, `inward`
// its normal into the room (both horizontal, unit).
struct WallFrame {
  Eigen::Vector3d origin, along, inward;
  double length = 0.0, height = 0.0;
  // Point s along the wall, z up it, `offset` in front of it.
  Eigen::Vector3d at(double s, double z, double offset) const {
    return origin + s * along + z * Eigen::Vector3d::UnitZ() + offset * inward;
  }
  // Rotation whose local axes are (along, up, inward).
  Eigen::Matrix3d axes() const;
};

class SceneBuilder {
 public:
  explicit SceneBuilder(std::uint64_t seed) : rng_(seed, RandomStream::kScene, 0) {}

  int texture(const Texture& texture);
  // A texture seeded from the scene's random source.
  int texture(TextureKind kind, double albedo, double albedo2, double scale, double roughness = 0.04);

  void rect(const Eigen::Vector3d& center, const Eigen::Matrix3d& axes, double half_x, double half_y, int texture);
  // A rectangle of glass (Primitive::glass): its texture is never seen.
  void glassPane(const Eigen::Vector3d& center, const Eigen::Matrix3d& axes, double half_x, double half_y,
                 int texture);
  void box(const Eigen::Vector3d& center, const Eigen::Matrix3d& axes, const Eigen::Vector3d& half, int texture);
  // An upright box given its footprint centre, yaw and full sizes, standing on z0.
  void uprightBox(const Eigen::Vector2d& xy, double yaw, const Eigen::Vector3d& size, double z0, int texture);
  // A box on a wall: s, z of its lower-left corner, sizes along the wall, up, out.
  void wallBox(const WallFrame& wall, double s, double z, const Eigen::Vector3d& size, int texture);
  void cylinder(const Eigen::Vector2d& xy, double z0, double z1, double radius, int texture);
  void sphere(const Eigen::Vector3d& center, double radius, int texture);

  // Copies of the primitives added from `first` on, moved by `shift`, with
  // the same textures: an identical twin of what was built since.
  std::size_t primitiveCount() const { return primitives_.size(); }
  void repeatShifted(std::size_t first, const Eigen::Vector3d& shift);

  CounterRandom& rng() { return rng_; }
  World build() const { return World(primitives_, textures_); }

 private:
  CounterRandom rng_;
  std::vector<Primitive> primitives_;
  std::vector<Texture> textures_;
};

Eigen::Matrix3d yawRotation(double yaw);

}  // namespace lvslam::sim
