#include "lidar/synthetic_lidar.h"

#include <cmath>
#include <limits>

#include "lvslam/core/se3.h"

namespace lvslam::testing {

namespace {

std::optional<double> castBox(const SyntheticScene::Box& box, const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
  double t_near = -std::numeric_limits<double>::infinity(), t_far = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (std::abs(d[a]) < 1e-12) {
      if (o[a] < box.min[a] || o[a] > box.max[a]) return std::nullopt;
      continue;
    }
    double t0 = (box.min[a] - o[a]) / d[a], t1 = (box.max[a] - o[a]) / d[a];
    if (t0 > t1) std::swap(t0, t1);
    t_near = std::max(t_near, t0);
    t_far = std::min(t_far, t1);
  }
  if (t_near > t_far || t_near <= 0) return std::nullopt;
  return t_near;
}

std::optional<double> castPole(const SyntheticScene::Pole& pole, const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
  const Eigen::Vector2d oc = o.head<2>() - pole.center;
  const double a = d.head<2>().squaredNorm();
  const double b = 2.0 * oc.dot(d.head<2>());
  const double c = oc.squaredNorm() - pole.radius * pole.radius;
  const double disc = b * b - 4 * a * c;
  if (a < 1e-12 || disc < 0) return std::nullopt;
  const double t = (-b - std::sqrt(disc)) / (2 * a);
  const double z = o.z() + t * d.z();
  if (t <= 0 || z < pole.z0 || z > pole.z1) return std::nullopt;
  return t;
}

}  // namespace

std::optional<double> SyntheticScene::cast(const Eigen::Vector3d& o, const Eigen::Vector3d& d) const {
  std::optional<double> best;
  auto consider = [&](std::optional<double> t) {
    if (t && (!best || *t < *best)) best = t;
  };
  for (const Plane& plane : planes) {
    const double nd = plane.n.dot(d);
    if (std::abs(nd) > 1e-12) {
      const double t = (plane.d - plane.n.dot(o)) / nd;
      if (t > 0) consider(t);
    }
  }
  for (const Box& box : boxes) consider(castBox(box, o, d));
  for (const Pole& pole : poles) consider(castPole(pole, o, d));
  return best;
}

SyntheticScene structuredRoom() {
  SyntheticScene s;
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(), z = Eigen::Vector3d::UnitZ();
  s.planes = {{z, 0.0}, {z, 4.0}, {x, -12.0}, {x, 12.0}, {y, -7.0}, {y, 7.0}};
  s.boxes = {{{3, 2, 0}, {4.2, 3.5, 1.2}}, {{-6, -4, 0}, {-4.5, -3, 0.8}}, {{-2, 4, 0}, {0, 5, 2}},
             {{-12, -1, 3.3}, {12, -0.7, 3.6}}, {{7, -6, 0}, {9, -5, 1.5}}};
  s.poles = {{{5, -2}, 0.2, 0, 4}, {{-3, -1.5}, 0.25, 0, 4}, {{-8, 3}, 0.2, 0, 4}, {{8, 4}, 0.3, 0, 4},
             {{0, -4.5}, 0.15, 0, 4}};
  return s;
}

SyntheticScene floorOnly() {
  SyntheticScene s;
  s.planes = {{Eigen::Vector3d::UnitZ(), 0.0}};
  return s;
}

LidarScan castScan(const SyntheticScene& scene, const PoseAtTime& T_world_lidar, double t0,
                   const SyntheticSensor& sensor, std::mt19937* rng, std::vector<Eigen::Vector3d>* world_hits) {
  LidarScan scan;
  scan.timestamp = t0;
  scan.has_time = scan.has_ring = true;
  std::normal_distribution<double> noise(0.0, 1.0);
  for (int c = 0; c < sensor.columns; ++c) {
    const double dt = sensor.period * c / sensor.columns;
    const Eigen::Isometry3d T = T_world_lidar(t0 + dt);
    const double azimuth = 2.0 * M_PI * c / sensor.columns;
    for (int r = 0; r < sensor.rings; ++r) {
      const double elevation = (sensor.min_elevation_deg +
                                (sensor.max_elevation_deg - sensor.min_elevation_deg) * r / (sensor.rings - 1)) *
                               M_PI / 180.0;
      const Eigen::Vector3d local(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                                  std::sin(elevation));
      const auto range = scene.cast(T.translation(), T.linear() * local);
      if (!range || *range > sensor.max_range) continue;
      const double noisy = *range + (rng && sensor.range_noise > 0 ? sensor.range_noise * noise(*rng) : 0.0);
      LidarPoint point;
      point.p = (local * noisy).cast<float>();
      point.time = static_cast<float>(dt);
      point.ring = static_cast<std::uint16_t>(r);
      scan.points.push_back(point);
      if (world_hits) world_hits->push_back(T.translation() + T.linear() * local * *range);
    }
  }
  return scan;
}

Eigen::Isometry3d drivePose(double t) {
  // ~1.2 m/s along a gentle S-curve through the hall, with a little pitch and roll.
  const double x = -6.0 + 1.2 * t;
  const double y = 1.5 * std::sin(0.4 * t);
  const double yaw = std::atan2(1.5 * 0.4 * std::cos(0.4 * t), 1.2);
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(0.02 * std::sin(1.3 * t), Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(0.02 * std::cos(1.1 * t), Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  return makePose(R, Eigen::Vector3d(x, y, 1.0 + 0.03 * std::sin(2.0 * t)));
}

}  // namespace lvslam::testing
