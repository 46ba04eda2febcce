#pragma once
// Output fusion: in fused mode the output pose of a frame the visual
// subsystem tracked is the information-weighted mean of its visual pose and
// the LiDAR odometry's pose at the same camera time, both in the odometry
// frame (lvslam's addition to the paper, whose output is the visual
// pose alone; docs/benchmarks.md, "Output fusion"). The two errors are nearly
// independent and complementary: vision pins the rotation and the image-plane
// translation of near scenes, the LiDAR the translation everywhere.
#include <Eigen/Geometry>

#include "lvslam/core/se3.h"
#include "lvslam/system/visual_band_pass.h"

namespace lvslam::system {

struct PoseFusionConfig {
  bool enabled = true;
  // The LiDAR pose at a camera time: isotropic noise of the camera centre
  // and of the rotation.
  double lidar_sigma_m = 0.005;
  double lidar_sigma_deg = 0.15;
  // The LiDAR odometry drifts: over a path of s metres since the visual
  // landmarks a pose rests on were mapped (and pulled onto the odometry of
  // that time, visual/module/odometry_map_correction.h), its error against
  // them grows by these per sqrt(m) (a random walk in path length). The
  // error both share up to then is common and leaves the weights alone.
  // Measured on the LiDAR odometry of a 300 s hall: relative error 7 mm at
  // 1-2 m, 14 mm at 8 m, 23 mm at 16 m (docs/benchmarks.md, "Drift-aware
  // output fusion"). 0: off.
  double lidar_drift_m = 0.005;
  double lidar_drift_deg = 0.03;
  // The tracker's information assumes 1 px of noise per ORB level-0
  // observation and exact landmarks; this inflates it to what it is (the
  // map's own error included). Chosen on the seed-1 room, hall and gate
  // among 1, 3, 6 and 10 (docs/benchmarks.md, "Output fusion"); 10 until the
  // output took the visual poses on the final keyframes, then 6 among 4, 6
  // and 10 on the nine bench sequences ("Frames on the final keyframes").
  double visual_pixel_sigma = 6.0;
  // The output's correction of the LiDAR pose changes by at most this much
  // per frame (output_correction.h).
  double max_step_m = 0.002;
  double max_step_deg = 0.05;
  // Then a share of vision's fast motion (visual_band_pass.h).
  VisualBandPassConfig band_pass;
};

// Information of a pose with isotropic camera-centre and rotation noise, for
// the left update T_camera_world <- exp(delta) T_camera_world: to first
// order the centre moves by -R^T rho and the rotation by phi.
Matrix6d isotropicPoseInformation(double sigma_m, double sigma_rad);

// The LiDAR pose's information after `path_m` metres of drift (above).
Matrix6d lidarPoseInformation(const PoseFusionConfig& config, double path_m);

// The information of a pose estimate without its translation-rotation
// coupling: the marginal information of the translation and of the
// rotation, each from the covariance, and no cross terms. The tracker's
// Hessian ties a sideways shift to a turn (far scenes), but its real errors
// do not follow that tie; joined with the LiDAR pose through it, a
// difference in rotation moved the centre (docs/benchmarks.md, "Decoupled
// visual information"). A direction the information does not know stays
// unknown.
Matrix6d decoupledInformation(const Matrix6d& information);

// The Gaussian product of two estimates of T_camera_world, linearised at
// the first: delta = (H_a + H_b)^-1 H_b log(T_b T_a^-1), T = exp(delta) T_a.
// Informations are for the left update (as above). Returns T_a when the sum
// is singular.
Eigen::Isometry3d fusePoses(const Eigen::Isometry3d& T_camera_world_a, const Matrix6d& information_a,
                            const Eigen::Isometry3d& T_camera_world_b, const Matrix6d& information_b);

}  // namespace lvslam::system
