#include "lvslam/system/offline/refinement.h"

#include "lvslam/system/offline/chunked_smoothing.h"
#include "lvslam/system/offline/loop_correction.h"
#include "lvslam/system/offline/loop_on_fused.h"

namespace lvslam::system {

namespace {

// The online estimator's graph over the whole run (each frame's LiDAR pose
// as the estimator last had it: interpolated between the sweeps around it;
// vision as tracked), smoothed with every node free but the first (the
// world), chunk by chunk (chunked_smoothing.h). Vision enters as tracked:
// its poses placed on the map's final keyframes gain nothing here (the
// estimator already weighs the map's drift) and lose where the final map
// is worse than the tracking was (docs/benchmarks.md, "Offline refinement").
Trajectory smoothFusedGraph(const PipelineRecords& records) {
  if (!records.estimator_graph) return {};
  const EstimatorGraph& graph = *records.estimator_graph;
  std::vector<PoseNode> nodes = graph.nodes;
  smoothInChunks(nodes, graph.factors, ChunkedSmoothingConfig{});
  Trajectory refined;
  for (const int node : graph.camera_nodes) {
    const auto i = static_cast<std::size_t>(node);
    refined.push_back({graph.times[i], nodes[i].T_world_camera});
  }
  return refined;
}

Trajectory replayWithFinalPoses(const PipelineRecords& records, const SystemConfig& config,
                                const Eigen::Isometry3d& T_camera_lidar) {
  const std::unique_ptr<OnlineOutput> output = makeOnlineOutput(config, T_camera_lidar, true);
  Trajectory refined;
  auto lidar = records.lidar.begin();
  for (const VisualFrameRecord& visual : records.visual) {
    const LidarFrameRecord* l = lidar != records.lidar.end() ? &*lidar : nullptr;
    const FrameOutput frame = output->add(&visual, l);
    if (frame.T_world_camera) refined.push_back({frame.t, *frame.T_world_camera});
    if (l) ++lidar;
  }
  return refined;
}

// Frames the replay could not pose (its world starts at the first LiDAR
// pose that stood after the run: when the sweeps after the first were lost,
// none does) keep their online pose; both are in the odometry frame.
Trajectory withOnlineWhereUnrefined(const Trajectory& refined, const Trajectory& online) {
  Trajectory merged;
  std::size_t r = 0, o = 0;
  while (r < refined.size() || o < online.size()) {
    const bool take_refined = o == online.size() || (r < refined.size() && refined[r].t <= online[o].t);
    if (take_refined) {
      if (o < online.size() && online[o].t == refined[r].t) ++o;
      merged.push_back(refined[r++]);
    } else {
      merged.push_back(online[o++]);
    }
  }
  return merged;
}

// The LiDAR odometry at each camera time as it stands after the run: each
// frame interpolated between the sweeps around it (the online output had
// only the sweep covering it).
Trajectory lidarAtFrames(const PipelineRecords& records, const Eigen::Isometry3d& T_camera_lidar) {
  Trajectory refined;
  for (const LidarFrameRecord& l : records.lidar)
    if (l.T_odom_lidar) refined.push_back({l.t, *l.T_odom_lidar * T_camera_lidar.inverse()});
  return refined;
}

Trajectory refineWithoutLoops(const PipelineRecords& records, const SystemConfig& config,
                              const Eigen::Isometry3d& T_camera_lidar, const Trajectory& online) {
  if (config.mode == RunMode::kLidar) return records.lidar.empty() ? online : lidarAtFrames(records, T_camera_lidar);
  if (config.mode == RunMode::kFused && !config.paper_output)
    return withOnlineWhereUnrefined(smoothFusedGraph(records), online);
  if (!config.final_map_poses) return online;
  return replayWithFinalPoses(records, config, T_camera_lidar);
}

}  // namespace

Refinement refineTrajectory(const PipelineRecords& records, const SystemConfig& config,
                            const Eigen::Isometry3d& T_camera_lidar, const Trajectory& online) {
  Refinement out{refineWithoutLoops(records, config, T_camera_lidar, online), records.loop};
  if (!records.loop) return out;
  // The LiDAR odometry of the refined poses' sensor: the camera's per frame, else the LiDAR's per scan.
  const Trajectory odometry = records.lidar.empty() ? records.T_odom_lidar_scans : lidarAtFrames(records, T_camera_lidar);
  std::optional<loop::LoopClosureResult> on_fused;
  if (config.mode == RunMode::kFused && !config.paper_output)
    on_fused = loopOnFusedTrajectory(*records.loop, out.trajectory, odometry, config.loop);
  if (on_fused) out.loop = on_fused;
  if (out.loop->accepted() == 0 || !out.loop->solved) return out;
  // On the fused poses the corrections apply to the refined poses themselves.
  out.trajectory = correctTrajectory(out.trajectory, on_fused ? out.trajectory : odometry, LoopCorrection(*out.loop));
  return out;
}

}  // namespace lvslam::system
