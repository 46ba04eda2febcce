#pragma once
// The unit sphere centred at the camera, where the fusion framework meets
// image lines and LiDAR features (paper, "Depth and direction association").
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace lvslam::fusion {

// Unit bearing of a point in the camera frame (zero vector for the origin).
Eigen::Vector3d bearing(const Eigen::Vector3d& p_camera);

// Great-circle arc from unit vector a to unit vector b, sampled at angle
// steps of exactly `step` radians from a, with b itself as the last sample
// (the paper's uniform sampling at interval delta_phi). a == b gives {a}.
std::vector<Eigen::Vector3d> sampleArc(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double step);

// Angle between two unit vectors, stable for small angles.
double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

// Angle on the sphere for a chord length between unit vectors.
double chordToAngle(double chord);

}  // namespace lvslam::fusion
