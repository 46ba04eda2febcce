#include "lvslam/fusion/line_reconstruction.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "lvslam/fusion/line_geometry.h"
#include "lvslam/fusion/sphere_geometry.h"

namespace lvslam::fusion {

namespace {

constexpr double kDegToRad = M_PI / 180.0;

struct Neighbours {
  std::vector<std::size_t> planar, linear, all;
  std::size_t samples = 0, matched = 0;
};

// The nearest LiDAR feature of every arc sample, kept when close on the sphere.
Neighbours gatherNeighbours(const std::vector<Eigen::Vector3d>& samples, const std::vector<SphereFeature>& features,
                            const SphereIndex& index, double max_angle) {
  Neighbours n;
  n.samples = samples.size();
  std::set<std::size_t> seen;
  for (const auto& s : samples) {
    SphereNeighbour nb;
    if (!index.nearest(s, nb) || nb.angle > max_angle) continue;
    ++n.matched;
    if (!seen.insert(nb.index).second) continue;
    n.all.push_back(nb.index);
    const FeatureShape shape = features[nb.index].shape;
    if (shape == FeatureShape::kPlanar) n.planar.push_back(nb.index);
    if (shape == FeatureShape::kLinear) n.linear.push_back(nb.index);
  }
  return n;
}

struct Candidate {
  Line3 line;
  std::vector<std::size_t> support;  // feature indices the line was built from
};

// Case (1): the dominant plane of the planar neighbours meets the image
// segment's back-projected plane.
std::optional<Candidate> planarCandidate(const std::vector<std::size_t>& ids, const std::vector<SphereFeature>& f,
                                         const Plane& image_plane, const FusionConfig& c) {
  std::vector<Eigen::Vector3d> normals;
  for (const std::size_t i : ids) normals.push_back(f[i].direction_camera);
  const DirectionCluster cluster = dominantDirectionCluster(normals, c.cluster_angle_deg * kDegToRad);
  if (static_cast<int>(cluster.members.size()) < c.min_neighbours) return std::nullopt;
  Candidate cand;
  std::vector<Eigen::Vector3d> pts, nrm;
  for (const std::size_t m : cluster.members) {
    cand.support.push_back(ids[m]);
    pts.push_back(f[ids[m]].p_camera);
    nrm.push_back(f[ids[m]].direction_camera);
  }
  const auto plane = fitPlaneFromNormals(pts, nrm);
  if (!plane) return std::nullopt;
  const auto line = intersectPlanes(*plane, image_plane, c.min_plane_angle_deg * kDegToRad);
  if (!line) return std::nullopt;
  cand.line = *line;
  return cand;
}

// Case (2): the dominant direction cluster of the linear neighbours, L_best,
// through the centroid of its points.
std::optional<Candidate> linearCandidate(const std::vector<std::size_t>& ids, const std::vector<SphereFeature>& f,
                                         const FusionConfig& c) {
  std::vector<Eigen::Vector3d> dirs;
  for (const std::size_t i : ids) dirs.push_back(f[i].direction_camera);
  const DirectionCluster cluster = dominantDirectionCluster(dirs, c.cluster_angle_deg * kDegToRad);
  if (static_cast<int>(cluster.members.size()) < c.min_neighbours) return std::nullopt;
  Candidate cand;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const std::size_t m : cluster.members) {
    cand.support.push_back(ids[m]);
    centroid += f[ids[m]].p_camera;
  }
  cand.line = Line3{centroid / static_cast<double>(cluster.members.size()), cluster.mean_direction};
  return cand;
}

double distanceToLine(const Line3& line, const Eigen::Vector3d& p) {
  const Eigen::Vector3d v = p - line.point;
  return (v - v.dot(line.direction) * line.direction).norm();
}

// Share of neighbours whose distance to the line is small against their depth.
double depthInlierRatio(const Line3& line, const std::vector<std::size_t>& ids, const std::vector<SphereFeature>& f,
                        double max_relative_error) {
  if (ids.empty()) return 0.0;
  std::size_t inliers = 0;
  for (const std::size_t i : ids)
    if (distanceToLine(line, f[i].p_camera) <= max_relative_error * f[i].p_camera.norm()) ++inliers;
  return static_cast<double>(inliers) / static_cast<double>(ids.size());
}

}  // namespace

LineReconstructor::LineReconstructor(const PinholeCamera& camera, const FusionConfig& config)
    : camera_(camera), config_(config) {}

std::optional<FusionLine> LineReconstructor::reconstruct(const ImageSegment& segment,
                                                         const std::vector<SphereFeature>& features,
                                                         const SphereIndex& index, RejectReason* why) const {
  RejectReason ignored;
  RejectReason& reason = why ? *why : ignored;
  reason = RejectReason::kNone;
  const FusionConfig& c = config_;
  if (segment.length() < c.min_segment_length_px) return reason = RejectReason::kTooShort, std::nullopt;

  const Eigen::Vector3d ray_a = camera_.unproject(segment.start).normalized();
  const Eigen::Vector3d ray_b = camera_.unproject(segment.end).normalized();
  const auto image_plane = backProjectedPlane(ray_a, ray_b);
  if (!image_plane) return reason = RejectReason::kDegenerate, std::nullopt;

  const Neighbours nb = gatherNeighbours(sampleArc(ray_a, ray_b, c.arc_step_deg * kDegToRad), features, index,
                                         c.max_neighbour_angle_deg * kDegToRad);
  if (static_cast<double>(nb.matched) < c.min_matched_ratio * static_cast<double>(nb.samples) ||
      static_cast<int>(nb.all.size()) < c.min_neighbours)
    return reason = RejectReason::kFarOnSphere, std::nullopt;

  const double total = static_cast<double>(nb.all.size());
  const bool planar_case = nb.planar.size() >= c.majority_ratio * total;
  const bool linear_case = nb.linear.size() >= c.majority_ratio * total;
  if (!planar_case && !linear_case) return reason = RejectReason::kMixedShapes, std::nullopt;

  const auto planar = planarCandidate(nb.planar, features, *image_plane, c);
  const auto linear = linearCandidate(nb.linear, features, c);
  const std::optional<Candidate>& chosen = planar_case ? planar : linear;
  if (!chosen) return reason = RejectReason::kDegenerate, std::nullopt;
  // Where both shapes have enough support, their answers must agree.
  if (planar && linear &&
      std::abs(planar->line.direction.dot(linear->line.direction)) < std::cos(c.max_case_disagreement_deg * kDegToRad))
    return reason = RejectReason::kCasesDisagree, std::nullopt;
  // The linear answer must lie in the plane of the image segment.
  if (!planar_case && std::abs(chosen->line.direction.dot(image_plane->n)) > std::sin(c.max_line_off_plane_deg * kDegToRad))
    return reason = RejectReason::kCasesDisagree, std::nullopt;
  if (depthInlierRatio(chosen->line, nb.all, features, c.max_relative_depth_error) < c.min_depth_inlier_ratio)
    return reason = RejectReason::kDepthInconsistent, std::nullopt;

  // Endpoints from the segment's end rays (exact on the line in the planar case).
  const auto A = closestPointOnLineToRay(chosen->line, ray_a);
  const auto B = closestPointOnLineToRay(chosen->line, ray_b);
  if (!A || !B || (*B - *A).norm() < 1e-6) return reason = RejectReason::kDegenerate, std::nullopt;
  for (const auto* p : {&*A, &*B})
    if (p->z() <= 0.0 || p->norm() < c.min_depth || p->norm() > c.max_depth)
      return reason = RejectReason::kOutOfRange, std::nullopt;

  FusionLine out;
  out.A = *A;
  out.B = *B;
  out.direction = (*B - *A).normalized();
  out.kind = planar_case ? FusionLineKind::kPlaneIntersection : FusionLineKind::kLinearCluster;
  out.neighbours = static_cast<int>(nb.all.size());
  if (!planar_case)
    for (const std::size_t i : chosen->support) out.linear_feature_ids.push_back(features[i].id);
  return out;
}

}  // namespace lvslam::fusion
