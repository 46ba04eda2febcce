#pragma once
// Counter-based random numbers: every draw is a pure function of (seed,
// stream, index), so rendering rows or LiDAR columns on any number of threads
// gives the same bytes (Steele et al., SplitMix64).
#include <cmath>
#include <cstdint>

namespace lvslam::sim {

inline std::uint64_t splitMix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

inline std::uint64_t hashCombine(std::uint64_t a, std::uint64_t b) { return splitMix64(a ^ splitMix64(b)); }

// Sensor streams of the simulator, so camera and LiDAR never share draws.
enum class RandomStream : std::uint64_t { kScene = 1, kCamera = 2, kLidar = 3, kTrajectory = 4, kExtrinsics = 5 };

// A small generator for one (seed, stream, frame) triple; draws are
// reproducible in the order they are made.
class CounterRandom {
 public:
  CounterRandom(std::uint64_t seed, RandomStream stream, std::uint64_t frame)
      : key_(hashCombine(hashCombine(seed, static_cast<std::uint64_t>(stream)), frame)) {}

  // Uniform in [0, 1) for draw `index` (stateless).
  double uniformAt(std::uint64_t index) const {
    return static_cast<double>(hashCombine(key_, index) >> 11) * 0x1.0p-53;
  }
  // Standard normal for draw `index` (Box-Muller on two stateless uniforms).
  double normalAt(std::uint64_t index) const { return normalPairAt(index).x; }
  // Two independent standard normals for one draw (both Box-Muller outputs).
  struct NormalPair {
    double x, y;
  };
  NormalPair normalPairAt(std::uint64_t index) const {
    // Indices apart from uniformAt's so the two kinds of draw never coincide.
    const std::uint64_t base = (1ULL << 62) + 2 * index;
    const double radius = std::sqrt(-2.0 * std::log(1.0 - uniformAt(base)));  // 1 - u in (0, 1]
    const double angle = 6.283185307179586 * uniformAt(base + 1);
    return {radius * std::cos(angle), radius * std::sin(angle)};
  }

  // Sequential draws for building scenes.
  double uniform() { return uniformAt(counter_++); }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  double normal() { return normalAt(counter_++); }

 private:
  std::uint64_t key_;
  std::uint64_t counter_ = 0;
};

}  // namespace lvslam::sim
