#pragma once
// A complete simulated recording setup: world, robot motion, rig, sensors and
// light. makeScenario builds the M2DGR-like scenes (room, hall, gate) and the
// scenes of the families (corridor, yard, office, atrium; families.h).
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/core/camera.h"
#include "lvslam/sim/auto_exposure.h"
#include "lvslam/sim/lidar_beam.h"
#include "lvslam/sim/robot_trajectory.h"
#include "lvslam/sim/sim_options.h"
#include "lvslam/sim/walking_person.h"
#include "lvslam/sim/world.h"

namespace lvslam::sim {

// Sensors on the robot. Body: x forward, y left, z up, origin on the ground.
struct Rig {
  Eigen::Isometry3d T_body_lidar = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T_body_camera = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T_camera_lidar() const { return T_body_camera.inverse() * T_body_lidar; }
};

struct CameraConfig {
  PinholeCamera camera;
  double rate_hz = 15.0;
  double start_offset = 0.0;   // first exposure, seconds after the sequence start
  double exposure = 0.012;     // seconds the shutter is open (motion blur)
  int blur_samples = 1;        // sub-exposures averaged; 1 = sharp
  double gain = 200.0;         // digital number per unit radiance
  double read_noise = 1.5;     // DN, Gaussian
  double shot_noise = 0.12;    // DN per sqrt(DN)
  double vignetting = 0.25;    // brightness lost at the image corners
  // Rolling shutter: seconds between the exposures of consecutive rows (0:
  // global shutter). Row y is exposed around t + (y - (height - 1) / 2) *
  // line_time, so the time stamp t is the middle of the middle row's exposure.
  double line_time = 0.0;
  AutoExposureConfig auto_exposure;  // off: every frame at `exposure` and `gain`
};

struct LidarConfig {
  std::vector<double> elevations_deg;  // one per ring, ascending (ring 0 lowest)
  int columns = 1800;                  // firings per revolution (0.2 deg)
  double rate_hz = 10.0;
  double start_offset = 0.0;           // first sweep start, seconds after the sequence start
  double range_noise = 0.015;          // metres, Gaussian along the ray (sigma0 of rangeSigma)
  double range_noise_per_metre = 0.0;  // sigma grows by this per metre of range
  double min_cos_incidence = 1.0;      // sigma / max(cos incidence, this); 1: no incidence effect
  double min_range = 0.5, max_range = 100.0;
  double dropout = 0.01;               // probability of a lost return on a good surface
  BeamModel beam;                      // footprint (mixed returns) and glass
};

struct PointLight {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double power = 0.0;  // radiance factor at 1 m, facing the light
};

struct Lighting {
  double ambient = 0.4;
  Eigen::Vector3d toward_light = Eigen::Vector3d::UnitZ();  // unit, direction to the main light
  double directional = 0.6;
  std::vector<PointLight> lamps;
  double sky = 1.3;  // radiance of a ray that hits nothing (open sky)
};

struct Scenario {
  std::string name;
  SimOptions options;
  World world;
  RobotTrajectory trajectory;
  Rig rig;
  CameraConfig camera;
  LidarConfig lidar;
  Lighting lighting;
  std::vector<WalkingPerson> people;  // options.people (at least one with options.walking_person)

  // Poses at t seconds after the sequence start (the renderer's own poses).
  Eigen::Isometry3d T_world_body(double t) const { return trajectory.T_world_body(t); }
  Eigen::Isometry3d T_world_camera(double t) const { return T_world_body(t) * rig.T_body_camera; }
  Eigen::Isometry3d T_world_lidar(double t) const { return T_world_body(t) * rig.T_body_lidar; }
};

// Throws lvslam::Error naming the option when the options are invalid.
Scenario makeScenario(const SimOptions& options);
Scenario makeScenario(const std::string& name, SimOptions options);

}  // namespace lvslam::sim
