#include "lvslam/sim/lidar_simulator.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <optional>

#include <tbb/parallel_for.h>

#include "lvslam/sim/counter_random.h"
#include "lvslam/sim/lidar_beam.h"

namespace lvslam::sim {

namespace {

constexpr double kTwoPi = 6.283185307179586;
// Draw indices of the glass decisions, apart from the noise and dropout draws.
constexpr std::uint64_t kGlassDraws = 1ULL << 40;

// Probability that a return is lost: a base rate, more at grazing incidence
// and on nearly black surfaces (too little light comes back).
double dropoutProbability(double base, double cos_incidence, double albedo) {
  return base + 0.5 * std::max(0.0, 0.12 - cos_incidence) / 0.12 + (albedo < 0.06 ? 0.3 : 0.0);
}

// The surface a pulse's ray met: a primitive, a person (-1) or nothing (-2).
int surfaceOf(const std::optional<WorldHit>& hit) { return hit ? hit->primitive : -2; }

}  // namespace

LidarScan LidarSimulator::scanLidar(double t_start) const {
  const LidarConfig& config = scenario_.lidar;
  const int rings = static_cast<int>(config.elevations_deg.size());
  const int columns = config.columns;
  const double column_dt = sweepDuration() / columns;
  const CounterRandom rng(scenario_.options.seed, RandomStream::kLidar, std::bit_cast<std::uint64_t>(t_start));
  const BeamCaster beams(scenario_.world, config.beam);
  // Per column (its firing instant): the sensor pose and the people.
  std::vector<Eigen::Isometry3d> T_world_column(columns);
  std::vector<std::vector<Primitive>> people(columns);
  tbb::parallel_for(0, columns, [&](int c) {
    T_world_column[c] = scenario_.T_world_lidar(t_start + c * column_dt);
    people[c] = peopleAt(scenario_.people, t_start + c * column_dt);
  });
  // The head spins clockwise seen from above, starting behind the robot.
  const auto direction = [&](int c, int ring) {
    const double azimuth = M_PI - kTwoPi * c / columns;
    const double elevation = config.elevations_deg[ring] * M_PI / 180.0;
    return Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                           std::sin(elevation));
  };
  const auto slot = [&](int c, int ring) { return static_cast<std::uint64_t>(c) * rings + ring; };
  const auto cast = [&](int c, int ring, bool footprint) {
    const Eigen::Vector3d origin = T_world_column[c].translation();
    const Eigen::Vector3d dir_world = T_world_column[c].linear() * direction(c, ring);
    const double glass_draw = rng.uniformAt(kGlassDraws + slot(c, ring));
    return footprint ? beams.castFootprint(origin, dir_world, people[c], config.max_range + 1.0, glass_draw)
                     : beams.castRay(origin, dir_world, people[c], config.max_range + 1.0, glass_draw);
  };
  std::vector<std::optional<WorldHit>> hits(static_cast<std::size_t>(rings) * columns);
  tbb::parallel_for(0, columns, [&](int c) {
    for (int ring = 0; ring < rings; ++ring) hits[slot(c, ring)] = cast(c, ring, false);
  });
  if (config.beam.footprint) {
    // A footprint can straddle two surfaces only where the ray of a
    // neighbouring pulse (0.2 deg away in the ring, a ring away in the
    // column, both wider than the 3 mrad cone) met another one: only those
    // pulses are cast again as footprints.
    std::vector<char> at_edge(hits.size(), 0);
    tbb::parallel_for(0, columns, [&](int c) {
      for (int ring = 0; ring < rings; ++ring) {
        const int own = surfaceOf(hits[slot(c, ring)]);
        at_edge[slot(c, ring)] = own != surfaceOf(hits[slot((c + 1) % columns, ring)]) ||
                                 own != surfaceOf(hits[slot((c + columns - 1) % columns, ring)]) ||
                                 (ring > 0 && own != surfaceOf(hits[slot(c, ring - 1)])) ||
                                 (ring + 1 < rings && own != surfaceOf(hits[slot(c, ring + 1)]));
      }
    });
    tbb::parallel_for(0, columns, [&](int c) {
      for (int ring = 0; ring < rings; ++ring)
        if (at_edge[slot(c, ring)]) hits[slot(c, ring)] = cast(c, ring, true);
    });
  }
  std::vector<std::optional<LidarPoint>> points(hits.size());
  tbb::parallel_for(0, columns, [&](int c) {
    for (int ring = 0; ring < rings; ++ring) {
      const std::uint64_t draw = slot(c, ring);
      const auto& hit = hits[draw];
      if (!hit) continue;  // sky, or glass
      const Eigen::Vector3d dir = direction(c, ring);
      const double cos_incidence = std::abs(hit->normal.dot(T_world_column[c].linear() * dir));
      if (rng.uniformAt(draw) < dropoutProbability(config.dropout, cos_incidence, hit->albedo)) continue;
      const double sigma = rangeSigma(config.range_noise, config.range_noise_per_metre, config.min_cos_incidence,
                                      hit->distance, cos_incidence);
      const double range = hit->distance + sigma * rng.normalAt(draw);
      if (range < config.min_range || range > config.max_range) continue;
      LidarPoint point;
      point.p = (range * dir).cast<float>();
      point.intensity = static_cast<float>(std::round(255.0 * hit->albedo * (0.3 + 0.7 * cos_incidence)));
      point.time = static_cast<float>(c * column_dt);
      point.ring = static_cast<std::uint16_t>(ring);
      points[draw] = point;
    }
  });
  LidarScan scan;
  scan.timestamp = t_start;
  scan.has_intensity = scan.has_time = scan.has_ring = true;
  for (const auto& point : points)
    if (point) scan.points.push_back(*point);
  return scan;
}

}  // namespace lvslam::sim
