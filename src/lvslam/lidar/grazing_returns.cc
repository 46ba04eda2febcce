#include "lvslam/lidar/grazing_returns.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace lvslam::lidar {

std::vector<bool> grazingReturns(const std::vector<TimedPoint>& points, double radius) {
  std::vector<bool> grazing(points.size(), false);
  std::map<int, std::vector<std::size_t>> by_ring;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].ring >= 0) by_ring[points[i].ring].push_back(i);
  const float radius_sq = static_cast<float>(radius * radius);
  std::vector<std::pair<float, std::size_t>> line;
  for (const auto& [ring, members] : by_ring) {
    const std::size_t n = members.size();
    if (n < 3) continue;
    line.clear();
    for (const std::size_t i : members) line.emplace_back(std::atan2(points[i].p.y(), points[i].p.x()), i);
    std::sort(line.begin(), line.end());
    for (std::size_t k = 0; k < n; ++k) {
      // The ring closes on itself: the first and last returns are neighbours.
      const Eigen::Vector3f& p = points[line[k].second].p;
      const Eigen::Vector3f& before = points[line[(k + n - 1) % n].second].p;
      const Eigen::Vector3f& after = points[line[(k + 1) % n].second].p;
      if ((before - p).squaredNorm() <= radius_sq || (after - p).squaredNorm() <= radius_sq) continue;
      const float r = p.norm(), r_before = before.norm(), r_after = after.norm();
      grazing[line[k].second] = (r_before < r && r < r_after) || (r_after < r && r < r_before);
    }
  }
  return grazing;
}

}  // namespace lvslam::lidar
