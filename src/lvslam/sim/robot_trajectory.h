#pragma once
// Motion of a ground robot: a closed C2 cubic spline through waypoints,
// driven at a speed limited by the turn rate and the acceleration, heading
// along the path, with the small roll, pitch and height shake of a platform
// on a real floor.
#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace lvslam::sim {

struct PathConfig {
  std::vector<Eigen::Vector2d> waypoints;  // closed loop, roughly evenly spaced, >= 3
  double max_speed = 0.4;                  // m/s
  double max_turn_rate = 0.5;              // rad/s: the speed drops in tight curves
  double acceleration = 0.3;               // m/s^2: start from rest and brake into curves
  double shake_deg = 0.3;                  // roll / pitch amplitude at full speed
  double shake_height = 0.003;             // metres
  double duration = 60.0;                  // seconds the table must cover
};

class RobotTrajectory {
 public:
  RobotTrajectory(const PathConfig& config, std::uint64_t seed);

  // Body pose (x forward, y left, z up, origin on the ground) at t seconds
  // after the start; held constant outside [0, duration].
  Eigen::Isometry3d T_world_body(double t) const;
  double speedAt(double t) const;

 private:
  struct Sample {
    double t, u, v;  // time, spline parameter (unwrapped), speed
  };
  Eigen::Vector2d position(double u) const;
  Eigen::Vector2d derivative(double u, int order) const;
  void buildSpline();
  void buildTimeTable();
  Sample sampleAt(double t) const;

  PathConfig config_;
  std::vector<Eigen::Vector2d> second_derivatives_;  // periodic spline moments
  std::vector<Sample> table_;
  std::array<double, 9> shake_phase_{};
};

}  // namespace lvslam::sim
