#include "lvslam/system/output_assembly.h"

#include <cmath>
#include <optional>

#include "lvslam/system/final_visual_poses.h"
#include "lvslam/system/offline/loop_correction.h"
#include "lvslam/system/offline/refinement.h"

namespace lvslam::system {

namespace {

PlySegment coloured(const Eigen::Vector3d& a, const Eigen::Vector3d& b, unsigned char r, unsigned char g) {
  PlySegment s;
  s.a = a;
  s.b = b;
  s.r = r;
  s.g = g;
  s.b_colour = 0;
  return s;
}

// Lines share map.ply's frame (the odometry's, which is fused mode's world),
// so after a loop closure each moves as the map points added at its time
// did (loop_correction.h).
void addLines(const PipelineRecords& records, const std::optional<LoopCorrection>& loop, SystemOutput& out) {
  const auto correctedAt = [&loop](std::optional<double> t) {
    return loop && t ? loop->atTime(*t) : Eigen::Isometry3d::Identity();
  };
  auto lidar = records.lidar.begin();
  for (auto frame = records.online.begin(); frame != records.online.end() && lidar != records.lidar.end();
       ++frame, ++lidar) {
    const auto& T = frame->T_world_camera;
    if (!T) continue;
    const Eigen::Isometry3d T_placed = correctedAt(frame->t) * *T;
    for (const CameraLine& line : lidar->fusion_lines)
      out.lines_world.push_back(coloured(T_placed * line.A, T_placed * line.B, 255, 0));
  }
  for (const MapLine& line : records.visual_lines) {
    const auto placed = out.T_world_map.find(line.map_id);  // a map never placed in the output: its lines neither
    if (placed == out.T_world_map.end()) continue;
    const Eigen::Isometry3d T_world_map = correctedAt(line.first_seen) * placed->second;
    out.lines_world.push_back(coloured(T_world_map * line.start, T_world_map * line.end, line.from_fusion ? 255 : 0,
                                       line.from_fusion ? 160 : 255));
  }
}

// The subsystems' own trajectories (SystemOutput::visual_maps, lidar_camera).
void addSubsystemTrajectories(const PipelineRecords& records, const SystemConfig& config,
                              const Eigen::Isometry3d& T_lidar_camera, SystemOutput& out) {
  for (const VisualFrameRecord& v : records.visual) {
    const auto& r = v.result;
    if (!r.pose_valid) continue;
    Trajectory& map = out.visual_maps[r.map_id];
    // The map's first view, an earlier frame.
    if (r.initial_reference) map.push_back(initialReferenceOf(v, config.final_map_poses));
    map.push_back({v.t, visualPoseOf(v, config.final_map_poses)});
  }
  if (config.mode != RunMode::kFused) return;
  for (const LidarFrameRecord& l : records.lidar)
    if (l.T_odom_lidar) out.lidar_camera.push_back({l.t, *l.T_odom_lidar * T_lidar_camera});
}

// The online poses in a saved map (--map-in). The localisation places the
// LiDAR odometry's frame (T_map_odom); fused mode's world is the
// estimator's, from which the odometry frame drifts (T_world_odom =
// T_world_camera T_odom_camera^-1 at a frame), taken at the frame nearest
// the localising keyframe; in lidar mode the world is the odometry's frame.
void placeInSavedMap(SystemOutput& out) {
  if (!out.loop || !out.loop->map_localization || !out.loop->map_localization->T_map_odom) return;
  const loop::MapLocalization& l = *out.loop->map_localization;
  Eigen::Isometry3d T_odom_world = Eigen::Isometry3d::Identity();
  const StampedPose* odom = nullptr;
  for (const StampedPose& p : out.lidar_camera)
    if (!odom || std::abs(p.t - l.localized_t) < std::abs(odom->t - l.localized_t)) odom = &p;
  if (odom) {
    for (const StampedPose& p : out.trajectory)
      if (p.t == odom->t) T_odom_world = odom->T_world_frame * p.T_world_frame.inverse();
  }
  const Eigen::Isometry3d T_map_world = *l.T_map_odom * T_odom_world;
  for (const StampedPose& p : out.trajectory) out.trajectory_in_map.push_back({p.t, T_map_world * p.T_world_frame});
}

}  // namespace

SystemOutput assembleOutput(const PipelineRecords& records, const SystemConfig& config,
                            const Eigen::Isometry3d& T_camera_lidar) {
  SystemOutput out;
  const Eigen::Isometry3d T_lidar_camera = T_camera_lidar.inverse();
  out.switches = records.switches;
  out.T_world_map = records.T_world_map;
  if (config.mode == RunMode::kLidar && records.lidar.empty()) {  // no camera: the LiDAR's own trajectory
    out.trajectory = records.T_odom_lidar_scans;
    out.trajectory_is_camera = false;
  }
  for (const FrameOutput& frame : records.online)
    if (frame.T_world_camera) out.trajectory.push_back({frame.t, *frame.T_world_camera});
  if (config.mode == RunMode::kVisual) {
    bool any_pose = false;
    for (const VisualFrameRecord& v : records.visual) {
      if (!v.result.pose_valid) continue;
      out.metric = any_pose ? out.metric && v.result.metric : v.result.metric;
      any_pose = true;
    }
  }
  Refinement refinement = refineTrajectory(records, config, T_camera_lidar, out.trajectory);
  out.trajectory_refined = std::move(refinement.trajectory);
  out.loop = std::move(refinement.loop);
  std::optional<LoopCorrection> loop;
  if (out.loop && out.loop->solved) loop.emplace(*out.loop);
  // The map's points are in the LiDAR odometry's frame: each moves from its
  // keyframe's odometry pose to the keyframe's corrected pose.
  out.lidar_map = loop ? correctMap(records.lidar_map, records.lidar_map_keyframe_starts,
                                    LoopCorrection(out.loop->keyframe_times, records.loop->T_odom_lidar,
                                                   out.loop->T_odom_lidar_corrected))
                       : records.lidar_map;
  addLines(records, loop, out);
  addSubsystemTrajectories(records, config, T_lidar_camera, out);
  placeInSavedMap(out);
  return out;
}

}  // namespace lvslam::system
