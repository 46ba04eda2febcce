#include "lvslam/sim/lidar_beam.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace lvslam::sim {

std::optional<WorldHit> BeamCaster::sample(const Eigen::Vector3d& origin, const Eigen::Vector3d& unit_dir,
                                           const std::vector<Primitive>& people, double max_range,
                                           bool through_glass) const {
  auto hit = world_.raycast(origin, unit_dir, max_range, model_.divergence, through_glass);
  for (const Primitive& person : people)
    addPersonHit(world_, person, origin, unit_dir, max_range, model_.divergence, hit);
  return hit;
}

std::optional<WorldHit> BeamCaster::castRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& unit_dir,
                                            const std::vector<Primitive>& people, double max_range,
                                            double glass_draw) const {
  auto hit = sample(origin, unit_dir, people, max_range, false);
  if (!hit || hit->primitive < 0 || !world_.primitives()[hit->primitive].glass) return hit;
  if (glass_draw >= model_.glass_return) return std::nullopt;  // reflected away from the sensor
  return sample(origin, unit_dir, people, max_range, true);
}

std::optional<WorldHit> BeamCaster::castFootprint(const Eigen::Vector3d& origin, const Eigen::Vector3d& unit_dir,
                                                  const std::vector<Primitive>& people, double max_range,
                                                  double glass_draw) const {
  // Two directions across the beam; the footprint is sampled at (+-1/4, +-1/4)
  // of its full angle, the centres of its four quarters.
  const Eigen::Vector3d helper = std::abs(unit_dir.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d across = unit_dir.cross(helper).normalized();
  const Eigen::Vector3d up = across.cross(unit_dir);
  const double q = 0.25 * model_.divergence;
  std::array<std::optional<WorldHit>, 4> hits;
  std::array<double, 4> energy{}, along{};
  int strongest = -1;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d dir = (unit_dir + q * ((i & 1) ? 1.0 : -1.0) * across + q * ((i & 2) ? 1.0 : -1.0) * up)
                                    .normalized();
    hits[i] = castRay(origin, dir, people, max_range, glass_draw);
    if (!hits[i]) continue;
    // Lambertian echo: reflectance times the cosine of incidence.
    energy[i] = hits[i]->albedo * std::abs(hits[i]->normal.dot(dir));
    along[i] = hits[i]->distance * dir.dot(unit_dir);  // the sample's range seen along the central ray
    if (strongest < 0 || energy[i] > energy[strongest]) strongest = i;
  }
  if (strongest < 0) return std::nullopt;
  // Echoes within the pulse length of the strongest overlap in the detector:
  // the sensor reports their energy-weighted mean range.
  double sum = 0.0, weight = 0.0;
  for (int i = 0; i < 4; ++i) {
    if (!hits[i] || std::abs(along[i] - along[strongest]) > model_.merge_distance) continue;
    sum += energy[i] * along[i];
    weight += energy[i];
  }
  WorldHit hit = *hits[strongest];
  hit.distance = weight > 0.0 ? sum / weight : along[strongest];
  return hit;
}

double rangeSigma(double sigma0, double per_metre, double min_cos, double range, double cos_incidence) {
  const double sigma = sigma0 + per_metre * range;
  return min_cos >= 1.0 ? sigma : sigma / std::max(cos_incidence, min_cos);
}

}  // namespace lvslam::sim
