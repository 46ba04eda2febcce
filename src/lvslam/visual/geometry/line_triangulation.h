#pragma once
// Two-view line triangulation: each observed segment back-projects to a plane
// pi_i = P_i^T l_i through its camera centre; the 3D line is the planes'
// intersection, read from the dual Plücker matrix L* = pi1 pi2^T - pi2 pi1^T
// (Cao et al., Sec. III-D "Line reconstruction with triangulation").
#include <optional>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "lvslam/core/plucker_line.h"

namespace lvslam::visual {

struct LineTriangulationConfig {
  // Planes meeting at a smaller angle are (near) degenerate: the line lies
  // close to the epipolar plane, passes near the epipole, or the baseline is tiny.
  double min_plane_angle_deg = 1.0;
  double max_depth = 100.0;  // metres, for the segment endpoints in both views
};

// One view: the pose T_camera_world and a segment's undistorted pixel endpoints.
struct LineView {
  Eigen::Isometry3d T_camera_world = Eigen::Isometry3d::Identity();
  Eigen::Vector2d start = Eigen::Vector2d::Zero();
  Eigen::Vector2d end = Eigen::Vector2d::Zero();
};

struct TriangulatedLine {
  PluckerLine line_world;       // |d| = 1
  Eigen::Vector3d start_world;  // endpoints of view 1's segment on the line
  Eigen::Vector3d end_world;
  double plane_angle_deg = 0.0;
};

// Dual Plücker matrix of two planes (4-vectors (n, e): n . x + e = 0).
Eigen::Matrix4d dualPluckerMatrix(const Eigen::Vector4d& pi1, const Eigen::Vector4d& pi2);
// The line (m, d) of a dual Plücker matrix [[d]x m; -m^T 0] (up to scale).
PluckerLine lineFromDualPlucker(const Eigen::Matrix4d& L_star);

// Plane in world coordinates through the camera centre and the segment's pixels.
Eigen::Vector4d backProjectedPlane(const Eigen::Matrix3d& K, const LineView& view);

// None when degenerate (planes too parallel, endpoints behind a camera or too
// far, non-finite input).
std::optional<TriangulatedLine> triangulateLine(const Eigen::Matrix3d& K, const LineView& view1,
                                                const LineView& view2,
                                                const LineTriangulationConfig& config = {});

}  // namespace lvslam::visual
