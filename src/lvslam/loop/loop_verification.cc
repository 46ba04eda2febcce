#include "lvslam/loop/loop_verification.h"

#include <algorithm>
#include <array>

#include <fmt/format.h>

#include "lvslam/lidar/local_map.h"
#include "lvslam/lidar/multi_metric_icp.h"

namespace lvslam::loop {

namespace {

// Correspondence distances (metres) from the coarse start (the descriptor
// knows the yaw to a sector, not the position) down to the registration's own.
constexpr std::array<double, 4> kThresholds = {2.0, 1.0, 0.5, 0.25};

lidar::LocalMap submapOf(const std::vector<SubmapScan>& submap, const lidar::LocalMapConfig& map_config) {
  lidar::LocalMap map(map_config);
  std::uint32_t seq = 0;
  for (const SubmapScan& scan : submap) {
    lidar::FeatureFrame frame;
    frame.seq = seq++;
    frame.T_world_lidar = scan.T_candidate_lidar;
    frame.points = *scan.points;
    map.update(frame);
  }
  return map;
}

}  // namespace

std::vector<SubmapScan> submapAround(const std::vector<LoopKeyframe>& keyframes, int candidate, int neighbours,
                                     int last) {
  const int first = std::max(0, candidate - neighbours);
  last = std::min(last, candidate + neighbours);
  const Eigen::Isometry3d T_candidate_odom = keyframes[static_cast<std::size_t>(candidate)].T_odom_lidar.inverse();
  std::vector<SubmapScan> submap;
  for (int k = first; k <= last; ++k) {
    const LoopKeyframe& kf = keyframes[static_cast<std::size_t>(k)];
    submap.push_back({T_candidate_odom * kf.T_odom_lidar, &kf.points});
  }
  return submap;
}

LoopVerification verifyLoop(const std::vector<lidar::FeaturePoint>& query, const std::vector<SubmapScan>& submap,
                            double yaw, const LoopClosureConfig& config, const lidar::RegistrationConfig& registration) {
  LoopVerification v;
  if (query.empty() || submap.empty()) {
    v.reason = "no features";
    return v;
  }
  lidar::LocalMapConfig map_config;
  map_config.radius = 2.0 * config.scan_context.max_radius;
  const lidar::LocalMap map = submapOf(submap, map_config);
  lidar::RegistrationConfig icp_config = registration;
  icp_config.max_iterations = 30;
  Eigen::Isometry3d T = Eigen::Isometry3d(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  lidar::IcpResult icp;
  for (const double threshold : kThresholds) {
    icp = lidar::registerMultiMetric(query, map, T, threshold, icp_config);
    if (icp.correspondences < icp_config.min_correspondences) break;
    T = icp.T_world_lidar;
  }
  v.T_candidate_query = icp.T_world_lidar;
  v.rms = icp.rms_residual;
  v.correspondences = icp.correspondences;
  v.inlier_ratio = static_cast<double>(icp.correspondences) / static_cast<double>(query.size());
  v.degenerate = icp.degenerate;
  v.localizability = icp.localizability;
  v.information = icp.information;
  if (icp.correspondences < icp_config.min_correspondences)
    v.reason = fmt::format("{} correspondences (< {})", icp.correspondences, icp_config.min_correspondences);
  else if (icp.degenerate)
    v.reason = fmt::format("degenerate (localizability {:.2g})", icp.localizability);
  else if (v.inlier_ratio < config.min_inlier_ratio)
    v.reason = fmt::format("inlier ratio {:.2f} (< {:.2f})", v.inlier_ratio, config.min_inlier_ratio);
  else if (v.rms > config.max_rms)
    v.reason = fmt::format("rms {:.3f} m (> {:.3f})", v.rms, config.max_rms);
  else if (!icp.converged)
    v.reason = "not converged";
  v.accepted = v.reason.empty();
  return v;
}

}  // namespace lvslam::loop
