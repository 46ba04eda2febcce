#include "lvslam/sim/texture.h"

#include <algorithm>
#include <cmath>

#include "lvslam/sim/counter_random.h"

namespace lvslam::sim {

namespace {

// A cheap lattice hash in [0, 1): textures need speed more than statistical
// quality (one multiply-xorshift round over the mixed coordinates).
double cellHash(std::uint64_t seed, std::int64_t i, std::int64_t j) {
  std::uint64_t h = seed * 0x9e3779b97f4a7c15ULL ^ static_cast<std::uint64_t>(i) * 0xc2b2ae3d27d4eb4fULL ^
                    static_cast<std::uint64_t>(j) * 0x165667b19e3779f9ULL;
  h ^= h >> 32;
  h *= 0xd6e8feb86659fd93ULL;
  h ^= h >> 32;
  h *= 0xd6e8feb86659fd93ULL;
  h ^= h >> 29;
  return static_cast<double>(h >> 11) * 0x1.0p-53;
}

// Smooth value noise in [0, 1] on a unit lattice.
double valueNoise(std::uint64_t seed, double x, double y) {
  const double fx = std::floor(x), fy = std::floor(y);
  const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy);
  const double sx = x - fx, sy = y - fy;
  const double wx = sx * sx * (3 - 2 * sx), wy = sy * sy * (3 - 2 * sy);
  const double a = cellHash(seed, ix, iy), b = cellHash(seed, ix + 1, iy);
  const double c = cellHash(seed, ix, iy + 1), d = cellHash(seed, ix + 1, iy + 1);
  return (a + (b - a) * wx) + ((c + (d - c) * wx) - (a + (b - a) * wx)) * wy;
}

// Fractal noise in about [-0.5, 0.5]; octaves finer than the footprint fade out.
double fractalNoise(std::uint64_t seed, const Eigen::Vector2d& uv, double base_period, double footprint,
                    int octaves = 3) {
  double sum = 0.0, amplitude = 0.5, period = base_period;
  for (int octave = 0; octave < octaves; ++octave) {
    const double keep = std::clamp(period / (2.0 * footprint) - 1.0, 0.0, 1.0);
    if (keep <= 0.0) break;
    sum += keep * amplitude * (valueNoise(seed + octave, uv.x() / period, uv.y() / period) - 0.5);
    amplitude *= 0.5;
    period *= 0.5;
  }
  return sum;
}

// Fraction of a pixel of size `footprint` covered by a line of half width
// `half_width` whose centre is `d` away (box-filtered step).
double lineCoverage(double d, double half_width, double footprint) {
  const double f = std::max(footprint, 1e-5);
  return std::clamp((half_width + 0.5 * f - std::abs(d)) / f, 0.0, 1.0);
}

// Distance to the nearest multiple of `period`.
double distanceToGrid(double x, double period) {
  const double r = x - period * std::floor(x / period);
  return std::min(r, period - r);
}

double mix(double a, double b, double w) { return a + (b - a) * w; }

double tiles(const Texture& tx, const Eigen::Vector2d& uv, double footprint) {
  const double s = tx.scale;
  const double shade = 0.8 + 0.4 * cellHash(tx.seed, static_cast<std::int64_t>(std::floor(uv.x() / s)),
                                            static_cast<std::int64_t>(std::floor(uv.y() / s)));
  const double d = std::min(distanceToGrid(uv.x(), s), distanceToGrid(uv.y(), s));
  return mix(tx.albedo * shade, tx.albedo2, lineCoverage(d, 0.004, footprint));
}

double bricks(const Texture& tx, const Eigen::Vector2d& uv, double footprint) {
  const double length = tx.scale, height = tx.scale / 3.0;
  const auto row = static_cast<std::int64_t>(std::floor(uv.y() / height));
  const double u = uv.x() + (row % 2 != 0 ? 0.5 * length : 0.0);
  const auto column = static_cast<std::int64_t>(std::floor(u / length));
  const double shade = 0.6 + 0.8 * cellHash(tx.seed, column, row);
  const double d = std::min(distanceToGrid(u, length), distanceToGrid(uv.y(), height));
  return mix(tx.albedo * shade, tx.albedo2, lineCoverage(d, 0.006, footprint));
}

double planks(const Texture& tx, const Eigen::Vector2d& uv, double footprint) {
  const auto row = static_cast<std::int64_t>(std::floor(uv.y() / tx.scale));
  const double shade = 0.8 + 0.4 * cellHash(tx.seed, 7, row);
  const double grain = fractalNoise(tx.seed + 11, Eigen::Vector2d(uv.x() * 0.1, uv.y() * 2.0), 0.05, footprint, 2);
  const double d = distanceToGrid(uv.y(), tx.scale);
  return mix(tx.albedo * (shade + 0.3 * grain), tx.albedo2, lineCoverage(d, 0.003, footprint));
}

// Cells of ink blocks, text bars and blank paper: corners and short lines.
double poster(const Texture& tx, const Eigen::Vector2d& uv, double footprint) {
  const double s = tx.scale;
  const auto i = static_cast<std::int64_t>(std::floor(uv.x() / s)), j = static_cast<std::int64_t>(std::floor(uv.y() / s));
  const double pick = cellHash(tx.seed, i, j);
  if (pick < 0.35) return mix(tx.albedo2, tx.albedo, 0.6 * cellHash(tx.seed + 1, i, j));  // ink block
  if (pick < 0.65) {  // text: bars a fifth of the cell high
    const double line = s / 5.0;
    const double v = uv.y() - line * std::floor(uv.y() / line);
    const double bar = lineCoverage(v - 0.5 * line, 0.22 * line, footprint);
    const double inset = lineCoverage(uv.x() - (i + 0.5) * s, 0.4 * s, footprint);
    return mix(tx.albedo, tx.albedo2, bar * inset);
  }
  return tx.albedo;
}

double bark(const Texture& tx, const Eigen::Vector2d& uv, double footprint) {
  const double streak = fractalNoise(tx.seed, Eigen::Vector2d(uv.x() * 8.0, uv.y() * 0.7), 0.4, footprint);
  return tx.albedo * (1.0 + 1.2 * streak);
}

double pattern(const Texture& tx, const Eigen::Vector2d& uv, double footprint) {
  switch (tx.kind) {
    case TextureKind::kPlain: return tx.albedo;
    case TextureKind::kNoise:
      return tx.albedo * (1.0 + 1.5 * fractalNoise(tx.seed, uv, tx.scale, footprint));
    case TextureKind::kTiles: return tiles(tx, uv, footprint);
    case TextureKind::kBricks: return bricks(tx, uv, footprint);
    case TextureKind::kPlanks: return planks(tx, uv, footprint);
    case TextureKind::kPoster: return poster(tx, uv, footprint);
    case TextureKind::kBark: return bark(tx, uv, footprint);
  }
  return tx.albedo;
}

}  // namespace

double albedoAt(const Texture& texture, const Eigen::Vector2d& uv, double footprint) {
  double a = pattern(texture, uv, footprint);
  // Patterns far smaller than a pixel average out (mean about the base albedo).
  const double fade = std::clamp((footprint / texture.scale - 0.3) / 0.5, 0.0, 1.0);
  a = mix(a, 0.85 * texture.albedo + 0.15 * texture.albedo2, fade);
  if (texture.roughness > 0.0) a += texture.roughness * fractalNoise(texture.seed + 101, uv, 0.3, footprint, 2);
  return std::clamp(a, 0.02, 1.0);
}

}  // namespace lvslam::sim
