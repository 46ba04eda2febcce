#include "lvslam/report/map_decimation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_set>

namespace lvslam::report {

namespace {

std::vector<PlyPoint> onePerVoxel(const std::vector<PlyPoint>& points, double voxel_m) {
  std::unordered_set<std::uint64_t> occupied;
  occupied.reserve(points.size());
  std::vector<PlyPoint> kept;
  for (const PlyPoint& q : points) {
    // 21 bits per axis: +-1M voxels, kilometres even at 5 cm.
    std::uint64_t key = 0;
    for (int axis = 0; axis < 3; ++axis)
      key = (key << 21) | (static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(q.p[axis] / voxel_m)) +
                                                      (1 << 20)) & 0x1fffff);
    if (occupied.insert(key).second) kept.push_back(q);
  }
  return kept;
}

}  // namespace

DecimatedMap decimateMap(const std::vector<PlyPoint>& points, std::size_t budget) {
  DecimatedMap map;
  if (points.size() <= budget) {
    map.points = points;
    return map;
  }
  // A map is mostly surfaces: the count falls about with the square of the
  // voxel edge, so each try jumps by that ratio (at least by a tenth).
  for (double voxel = 0.05;;) {
    map.points = onePerVoxel(points, voxel);
    map.voxel_m = voxel;
    if (map.points.size() <= budget) return map;
    voxel *= std::max(1.1, std::sqrt(static_cast<double>(map.points.size()) / static_cast<double>(budget)));
  }
}

}  // namespace lvslam::report
