#pragma once
// A synthetic room-like scene for the optimisation tests: cameras moving
// sideways in front of random points and line segments, and exact
// observations of them.
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/core/plucker_line.h"
#include "lvslam/core/se3.h"
#include "lvslam/visual/residuals/pose_block.h"

namespace lvslam::visual::testing {

struct Segment3d {
  Eigen::Vector3d a, b;
};

struct SyntheticScene {
  PinholeIntrinsics K{450.0, 450.0, 320.0, 240.0};
  int width = 640, height = 480;
  std::vector<Eigen::Isometry3d> T_camera_world;
  std::vector<Eigen::Vector3d> points;
  std::vector<Segment3d> segments;

  Eigen::Vector3d project(const Eigen::Isometry3d& T_c_w, const Eigen::Vector3d& p_w) const {
    const Eigen::Vector3d p = T_c_w * p_w;
    return Eigen::Vector3d(K.fx * p.x() / p.z() + K.cx, K.fy * p.y() / p.z() + K.cy, p.z());
  }
  bool visible(const Eigen::Vector3d& projected) const {
    return projected.z() > 0.1 && projected.x() >= 0 && projected.x() < width && projected.y() >= 0 &&
           projected.y() < height;
  }
};

inline SyntheticScene makeScene(int num_cameras, int num_points, int num_segments, double step, unsigned seed) {
  SyntheticScene s;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(-3.0, 3.0), y(-2.0, 2.0), z(4.0, 8.0), small(-0.03, 0.03);
  for (int k = 0; k < num_cameras; ++k) {
    Vector6d xi;
    xi << step * k, 0.3 * step * k, 0.0, small(rng), 0.02 * k + small(rng), small(rng);
    s.T_camera_world.push_back(expSE3(xi).inverse());  // cameras look along +z of the world
  }
  for (int i = 0; i < num_points; ++i) s.points.emplace_back(x(rng), y(rng), z(rng));
  while (static_cast<int>(s.segments.size()) < num_segments) {
    const Eigen::Vector3d a(x(rng), y(rng), z(rng)), b(x(rng), y(rng), z(rng));
    if ((a - b).norm() > 1.5) s.segments.push_back({a, b});
  }
  return s;
}

inline PluckerLine lineOf(const Segment3d& s) { return PluckerLine::fromPoints(s.a, s.b); }

// Distance between two lines as Plücker vectors (sign and scale free).
inline double sameLineError(const PluckerLine& a, const PluckerLine& b) {
  const Vector6d va = a.vector().normalized(), vb = b.vector().normalized();
  return std::min((va - vb).norm(), (va + vb).norm());
}

inline double angleBetweenLines(const PluckerLine& a, const PluckerLine& b) {
  return std::acos(std::min(1.0, std::abs(a.d.normalized().dot(b.d.normalized()))));
}

}  // namespace lvslam::visual::testing
