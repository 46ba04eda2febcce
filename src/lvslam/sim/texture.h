#pragma once
// Procedural surface textures in surface metres. Each gives a feature SLAM
// what real indoor and outdoor surfaces give: corners (tile crossings,
// poster blocks, brick ends) and long straight edges (grout, mortar, planks).
#include <cstdint>

#include <Eigen/Core>

namespace lvslam::sim {

enum class TextureKind {
  kPlain,   // albedo with faint noise (painted plaster, metal)
  kNoise,   // multi-octave value noise (asphalt, grass, gravel)
  kTiles,   // square tiles of side `scale` with grout lines, each tile its own shade
  kBricks,  // running-bond bricks `scale` long, a third as high, mortar joints
  kPlanks,  // horizontal boards `scale` high (shelves, doors, wood panels)
  kPoster,  // blocks of ink and text bars on paper in cells of `scale`
  kBark,    // vertical streaks (tree trunks)
};

struct Texture {
  TextureKind kind = TextureKind::kPlain;
  double albedo = 0.6;     // base reflectance in [0, 1]
  double albedo2 = 0.2;    // second reflectance: grout, mortar, ink
  double scale = 0.5;      // pattern size in metres
  double roughness = 0.04; // amplitude of the noise laid over the pattern
  std::uint64_t seed = 0;
};

// Reflectance at surface coordinates uv (metres). `footprint` is the size of
// the surface patch one pixel sees (metres): details below it fade to their
// mean, which is what a real lens does (no aliasing shimmer).
double albedoAt(const Texture& texture, const Eigen::Vector2d& uv, double footprint);

}  // namespace lvslam::sim
