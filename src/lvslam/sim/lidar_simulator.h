#pragma once
// A spinning multi-ring LiDAR (VLP-32C-like): every column of lasers fires at
// its own time while the robot moves, each ray cast from the sensor pose of
// that instant, so the scan is raw and motion-distorted like a real one.
// Range noise along the ray (growing with range and incidence when so
// configured), dropouts (more at grazing incidence and on dark surfaces), no
// return from the sky, glass or beyond the maximum range, intensity from
// albedo and incidence; each pulse a ray or a footprint (lidar_beam.h).
#include "lvslam/core/lidar_scan.h"
#include "lvslam/sim/scenario.h"

namespace lvslam::sim {

class LidarSimulator {
 public:
  // The scenario must outlive the simulator.
  explicit LidarSimulator(const Scenario& scenario) : scenario_(scenario) {}

  // One revolution starting at t_start (seconds after the sequence start);
  // the scan's timestamp is t_start and point times are relative to it.
  // Noise is keyed by (seed, t_start): the same call gives the same points.
  LidarScan scanLidar(double t_start) const;

  double sweepDuration() const { return 1.0 / scenario_.lidar.rate_hz; }

 private:
  const Scenario& scenario_;
};

}  // namespace lvslam::sim
