#include "lvslam/sim/primitive.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lvslam::sim {

namespace {

constexpr double kMinDistance = 1e-6;

const std::vector<std::array<int, 2>> kRectEdges{{0, 1}, {1, 2}, {2, 3}, {3, 0}};
// Corners indexed by bits (x, y, z) = (i & 1, i & 2, i & 4).
const std::vector<std::array<int, 2>> kBoxEdges{{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                                {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

Eigen::Vector3d toWorld(const Primitive& p, const Eigen::Vector3d& local) { return p.R * local + p.center; }

std::optional<SurfaceHit> intersectRect(const Primitive& p, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                                        double t_max) {
  if (std::abs(d.z()) < 1e-12) return std::nullopt;
  const double t = -o.z() / d.z();
  if (t < kMinDistance || t > t_max) return std::nullopt;
  const double x = o.x() + t * d.x(), y = o.y() + t * d.y();
  if (std::abs(x) > p.half.x() || std::abs(y) > p.half.y()) return std::nullopt;
  return SurfaceHit{t, Eigen::Vector3d(0, 0, d.z() > 0 ? -1.0 : 1.0), {x + p.half.x(), y + p.half.y()}};
}

// Slab test in the box's own frame.
std::optional<SurfaceHit> intersectBox(const Primitive& p, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                                       double t_max) {
  double t_near = -std::numeric_limits<double>::infinity(), t_far = std::numeric_limits<double>::infinity();
  int axis_near = 0, axis_far = 0;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(d[k]) < 1e-15) {
      if (std::abs(o[k]) > p.half[k]) return std::nullopt;
      continue;
    }
    double t0 = (-p.half[k] - o[k]) / d[k], t1 = (p.half[k] - o[k]) / d[k];
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > t_near) { t_near = t0; axis_near = k; }
    if (t1 < t_far) { t_far = t1; axis_far = k; }
  }
  if (t_near > t_far) return std::nullopt;
  // A ray starting inside (never for sensors) sees the inside of the far face.
  const bool inside = t_near < kMinDistance;
  const double t = inside ? t_far : t_near;
  const int axis = inside ? axis_far : axis_near;
  if (t < kMinDistance || t > t_max) return std::nullopt;
  SurfaceHit hit;
  hit.distance = t;
  hit.normal = Eigen::Vector3d::Zero();
  hit.normal[axis] = d[axis] > 0 ? -1.0 : 1.0;
  const Eigen::Vector3d q = o + t * d;
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  hit.uv = {q[a] + p.half[a], q[b] + p.half[b]};
  return hit;
}

// Smallest root above kMinDistance of |o + t d|^2 = r^2 restricted to the
// components in `mask` (xy for a cylinder side, xyz for a sphere).
std::optional<double> quadricRoot(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double r,
                                  const Eigen::Vector3d& mask) {
  const Eigen::Vector3d om = o.cwiseProduct(mask), dm = d.cwiseProduct(mask);
  const double a = dm.squaredNorm();
  if (a < 1e-18) return std::nullopt;
  const double b = om.dot(dm), c = om.squaredNorm() - r * r;
  const double disc = b * b - a * c;
  if (disc < 0.0) return std::nullopt;
  const double s = std::sqrt(disc);
  const double t0 = (-b - s) / a, t1 = (-b + s) / a;
  if (t0 >= kMinDistance) return t0;
  if (t1 >= kMinDistance) return t1;
  return std::nullopt;
}

std::optional<SurfaceHit> intersectCylinder(const Primitive& p, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                                            double t_max) {
  const double r = p.half.x(), h = p.half.z();
  std::optional<SurfaceHit> best;
  if (auto t = quadricRoot(o, d, r, Eigen::Vector3d(1, 1, 0)); t && *t <= t_max) {
    const Eigen::Vector3d q = o + *t * d;
    if (std::abs(q.z()) <= h) {
      Eigen::Vector3d n(q.x(), q.y(), 0.0);
      n /= r;
      if (n.dot(d) > 0) n = -n;
      best = SurfaceHit{*t, n, {std::atan2(q.y(), q.x()) * r, q.z() + h}};
    }
  }
  for (const double zc : {-h, h}) {
    if (std::abs(d.z()) < 1e-15) break;
    const double t = (zc - o.z()) / d.z();
    if (t < kMinDistance || t > t_max || (best && t >= best->distance)) continue;
    const Eigen::Vector3d q = o + t * d;
    if (q.x() * q.x() + q.y() * q.y() > r * r) continue;
    best = SurfaceHit{t, Eigen::Vector3d(0, 0, d.z() > 0 ? -1.0 : 1.0), {q.x() + r, q.y() + r}};
  }
  return best;
}

std::optional<SurfaceHit> intersectSphere(const Primitive& p, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                                          double t_max) {
  const double r = p.half.x();
  const auto t = quadricRoot(o, d, r, Eigen::Vector3d::Ones());
  if (!t || *t > t_max) return std::nullopt;
  const Eigen::Vector3d q = o + *t * d;
  Eigen::Vector3d n = q / r;
  if (n.dot(d) > 0) n = -n;
  const double polar = std::acos(std::clamp(q.z() / r, -1.0, 1.0));
  return SurfaceHit{*t, n, {std::atan2(q.y(), q.x()) * r, polar * r}};
}

double boxSurfaceDistance(const Eigen::Vector3d& q, const Eigen::Vector3d& half) {
  const Eigen::Vector3d excess = q.cwiseAbs() - half;
  if ((excess.array() > 0.0).any()) return excess.cwiseMax(0.0).norm();
  return -excess.maxCoeff();  // inside: distance to the nearest face
}

double cylinderSurfaceDistance(const Eigen::Vector3d& q, double r, double h) {
  const double dr = std::hypot(q.x(), q.y()) - r, dz = std::abs(q.z()) - h;
  if (dr > 0.0 && dz > 0.0) return std::hypot(dr, dz);
  if (dr > 0.0) return dr;
  if (dz > 0.0) return dz;
  return std::min(-dr, -dz);
}

}  // namespace

double AlignedBox::entryDistance(const Eigen::Vector3d& origin, const Eigen::Vector3d& inv_dir, double t_max) const {
  double t0 = 0.0, t1 = t_max;
  for (int k = 0; k < 3; ++k) {
    double a = (min[k] - origin[k]) * inv_dir[k], b = (max[k] - origin[k]) * inv_dir[k];
    if (a > b) std::swap(a, b);
    // NaN (0 * inf on a face) keeps the previous bound, which is conservative.
    t0 = a > t0 ? a : t0;
    t1 = b < t1 ? b : t1;
    if (t0 > t1) return std::numeric_limits<double>::infinity();
  }
  return t0;
}

double AlignedBox::distanceTo(const Eigen::Vector3d& p) const {
  return (min - p).cwiseMax(p - max).cwiseMax(0.0).norm();
}

std::optional<SurfaceHit> intersect(const Primitive& p, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                                    double t_max) {
  const Eigen::Vector3d o = p.R.transpose() * (origin - p.center);
  const Eigen::Vector3d d = p.R.transpose() * dir;
  std::optional<SurfaceHit> hit;
  switch (p.kind) {
    case PrimitiveKind::kRect: hit = intersectRect(p, o, d, t_max); break;
    case PrimitiveKind::kBox: hit = intersectBox(p, o, d, t_max); break;
    case PrimitiveKind::kCylinder: hit = intersectCylinder(p, o, d, t_max); break;
    case PrimitiveKind::kSphere: hit = intersectSphere(p, o, d, t_max); break;
  }
  if (hit) hit->normal = p.R * hit->normal;
  return hit;
}

double distanceToSurface(const Primitive& p, const Eigen::Vector3d& point) {
  const Eigen::Vector3d q = p.R.transpose() * (point - p.center);
  switch (p.kind) {
    case PrimitiveKind::kRect:
      return Eigen::Vector3d(std::max(std::abs(q.x()) - p.half.x(), 0.0), std::max(std::abs(q.y()) - p.half.y(), 0.0),
                             q.z())
          .norm();
    case PrimitiveKind::kBox: return boxSurfaceDistance(q, p.half);
    case PrimitiveKind::kCylinder: return cylinderSurfaceDistance(q, p.half.x(), p.half.z());
    case PrimitiveKind::kSphere: return std::abs(q.norm() - p.half.x());
  }
  return std::numeric_limits<double>::infinity();
}

BoundingPolytope boundingPolytope(const Primitive& p) {
  BoundingPolytope poly;
  if (p.kind == PrimitiveKind::kRect) {
    const double hx = p.half.x(), hy = p.half.y();
    for (const auto& c : {Eigen::Vector3d(-hx, -hy, 0), Eigen::Vector3d(hx, -hy, 0), Eigen::Vector3d(hx, hy, 0),
                          Eigen::Vector3d(-hx, hy, 0)})
      poly.corners.push_back(toWorld(p, c));
    poly.edges = &kRectEdges;
    return poly;
  }
  const Eigen::Vector3d h = p.kind == PrimitiveKind::kBox ? p.half
                            : p.kind == PrimitiveKind::kCylinder
                                ? Eigen::Vector3d(p.half.x(), p.half.x(), p.half.z())
                                : Eigen::Vector3d::Constant(p.half.x());
  for (int i = 0; i < 8; ++i)
    poly.corners.push_back(toWorld(p, Eigen::Vector3d(i & 1 ? h.x() : -h.x(), i & 2 ? h.y() : -h.y(),
                                                      i & 4 ? h.z() : -h.z())));
  poly.edges = &kBoxEdges;
  return poly;
}

AlignedBox bounds(const Primitive& p) {
  AlignedBox box;
  for (const auto& c : boundingPolytope(p).corners) box.extend(c);
  return box;
}

std::vector<std::array<Eigen::Vector3d, 2>> straightEdges(const Primitive& p) {
  std::vector<std::array<Eigen::Vector3d, 2>> edges;
  if (p.kind != PrimitiveKind::kRect && p.kind != PrimitiveKind::kBox) return edges;
  const BoundingPolytope poly = boundingPolytope(p);
  for (const auto& e : *poly.edges) edges.push_back({poly.corners[e[0]], poly.corners[e[1]]});
  return edges;
}

}  // namespace lvslam::sim
