#include "loop/loop_scenes.h"

#include "lvslam/lidar/deskew.h"
#include "lvslam/lidar/feature_extraction.h"
#include "lvslam/lidar/lidar_config.h"
#include "lvslam/lidar/preprocess.h"

namespace lvslam::testing {

SyntheticScene storeRoom() {
  SyntheticScene s;
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(), z = Eigen::Vector3d::UnitZ();
  s.planes = {{z, 0.0}, {z, 3.0}, {x, -8.0}, {x, 8.0}, {y, -5.0}, {y, 5.0}};
  // The L: a solid block fills one corner.
  s.boxes = {{{3, 1, 0}, {8, 5, 3}},         {{-7, -4.5, 0}, {-2, -3.9, 2.2}}, {{-7, 2, 0}, {-6.4, 4.5, 2.2}},
             {{-1, -1, 0}, {1.5, -0.4, 1.8}}, {{4, -4.6, 0}, {7.5, -4, 1.0}}};
  s.poles = {{{-3, 1}, 0.3, 0, 3}, {{2, -2.5}, 0.3, 0, 3}};
  return s;
}

std::vector<lidar::FeaturePoint> keyframeFeatures(const SyntheticScene& scene, const Eigen::Isometry3d& T_world_lidar) {
  const lidar::LidarOdometryConfig config;
  SyntheticSensor sensor;
  sensor.columns = 1024;
  const LidarScan scan = castScan(scene, [&](double) { return T_world_lidar; }, 0.0, sensor);
  return lidar::extractFeatures(lidar::cropAndDownsample(scan, config.preprocess, config.features.neighbour_radius), config.ground, config.features);
}

std::vector<lidar::FeaturePoint> keyframeFeatures(const sim::Scenario& scenario, const sim::LidarSimulator& lidar,
                                                  double t) {
  const lidar::LidarOdometryConfig config;
  const double sweep = lidar.sweepDuration();
  std::vector<lidar::TimedPoint> points =
      lidar::cropAndDownsample(lidar.scanLidar(t), config.preprocess, config.features.neighbour_radius);
  lidar::deskewToReference(points, lidar::velocityBetween(scenario.T_world_lidar(t), t,
                                                          scenario.T_world_lidar(t + sweep), t + sweep));
  return lidar::extractFeatures(points, config.ground, config.features);
}

}  // namespace lvslam::testing
