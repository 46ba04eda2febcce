#include "lvslam/sim/lidar_simulator.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <optional>

#include <tbb/parallel_for.h>

#include "lvslam/sim/counter_random.h"

namespace lvslam::sim {

namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr double kBeamDivergence = 0.003;  // radians (VLP-32C: 3 mrad), sets the albedo's footprint

// Probability that a return is lost: a base rate, more at grazing incidence
// and on nearly black surfaces (too little light comes back).
double dropoutProbability(double base, double cos_incidence, double albedo) {
  return base + 0.5 * std::max(0.0, 0.12 - cos_incidence) / 0.12 + (albedo < 0.06 ? 0.3 : 0.0);
}

}  // namespace

LidarScan LidarSimulator::scanLidar(double t_start) const {
  const LidarConfig& config = scenario_.lidar;
  const int rings = static_cast<int>(config.elevations_deg.size());
  const int columns = config.columns;
  const double column_dt = sweepDuration() / columns;
  const CounterRandom rng(scenario_.options.seed, RandomStream::kLidar, std::bit_cast<std::uint64_t>(t_start));
  std::vector<std::optional<LidarPoint>> slots(static_cast<std::size_t>(rings) * columns);
  tbb::parallel_for(0, columns, [&](int c) {
    const double time = c * column_dt;
    // The head spins clockwise seen from above, starting behind the robot.
    const double azimuth = M_PI - kTwoPi * c / columns;
    const Eigen::Isometry3d T_world_lidar = scenario_.T_world_lidar(t_start + time);
    for (int ring = 0; ring < rings; ++ring) {
      const double elevation = config.elevations_deg[ring] * M_PI / 180.0;
      const Eigen::Vector3d dir(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                                std::sin(elevation));
      const Eigen::Vector3d dir_world = T_world_lidar.linear() * dir;
      auto hit = scenario_.world.raycast(T_world_lidar.translation(), dir_world, config.max_range + 1.0,
                                         kBeamDivergence);
      if (scenario_.person)
        addPersonHit(scenario_.world, *scenario_.person, t_start + time, T_world_lidar.translation(), dir_world,
                     config.max_range + 1.0, kBeamDivergence, hit);
      if (!hit) continue;  // sky
      const std::uint64_t draw = static_cast<std::uint64_t>(c) * rings + ring;
      const double cos_incidence = std::abs(hit->normal.dot(dir_world));
      if (rng.uniformAt(draw) < dropoutProbability(config.dropout, cos_incidence, hit->albedo)) continue;
      const double range = hit->distance + config.range_noise * rng.normalAt(draw);
      if (range < config.min_range || range > config.max_range) continue;
      LidarPoint point;
      point.p = (range * dir).cast<float>();
      point.intensity = static_cast<float>(std::round(255.0 * hit->albedo * (0.3 + 0.7 * cos_incidence)));
      point.time = static_cast<float>(time);
      point.ring = static_cast<std::uint16_t>(ring);
      slots[draw] = point;
    }
  });
  LidarScan scan;
  scan.timestamp = t_start;
  scan.has_intensity = scan.has_time = scan.has_ring = true;
  for (const auto& slot : slots)
    if (slot) scan.points.push_back(*slot);
  return scan;
}

}  // namespace lvslam::sim
