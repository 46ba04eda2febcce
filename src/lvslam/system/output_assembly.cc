#include "lvslam/system/output_assembly.h"

#include <cmath>

#include "lvslam/system/output_correction.h"
#include "lvslam/system/odometry_path_length.h"
#include "lvslam/system/output_trajectory.h"
#include "lvslam/system/pose_fusion.h"
#include "lvslam/system/visual_band_pass.h"

namespace lvslam::system {

namespace {

VisualState stateOf(visual::TrackingState state) {
  switch (state) {
    case visual::TrackingState::kTracking: return VisualState::kTracking;
    case visual::TrackingState::kLost: return VisualState::kLost;
    case visual::TrackingState::kInitializing: break;
  }
  return VisualState::kInitializing;
}

// Visual against LiDAR camera motion between two consecutive frames, when both know it.
std::optional<MotionDisagreement> disagreement(const VisualFrameRecord& v0, const VisualFrameRecord& v1,
                                               const LidarFrameRecord& l0, const LidarFrameRecord& l1,
                                               const Eigen::Isometry3d& T_lidar_camera) {
  const auto& r0 = v0.result;
  const auto& r1 = v1.result;
  if (!r0.pose_valid || !r1.pose_valid || r0.map_id != r1.map_id || !l0.T_odom_lidar || !l1.T_odom_lidar)
    return std::nullopt;
  // A map correction in this frame moved the map under the camera: compare
  // the motion within the corrected map.
  const Eigen::Isometry3d T_world_camera0 = r1.T_new_old ? *r1.T_new_old * r0.T_world_camera : r0.T_world_camera;
  const Eigen::Isometry3d visual_motion = T_world_camera0.inverse() * r1.T_world_camera;
  const Eigen::Isometry3d lidar_motion =
      T_lidar_camera.inverse() * (l0.T_odom_lidar->inverse() * *l1.T_odom_lidar) * T_lidar_camera;
  const Eigen::Isometry3d difference = visual_motion.inverse() * lidar_motion;
  const double angle = Eigen::AngleAxisd(difference.rotation()).angle();
  return MotionDisagreement{difference.translation().norm(), angle * 180.0 / M_PI};
}

std::optional<MotionDisagreement> frameDisagreement(const PipelineRecords& records, std::size_t j,
                                                   const Eigen::Isometry3d& T_lidar_camera) {
  if (j == 0) return std::nullopt;
  return disagreement(records.visual[j - 1], records.visual[j], records.lidar[j - 1], records.lidar[j], T_lidar_camera);
}

// The frame's visual pose in its map: on the map's final keyframes when the
// configuration asks and they are known (final_visual_poses.h), else as tracked.
Eigen::Isometry3d visualPose(const VisualFrameRecord& v, bool final_map_poses) {
  return final_map_poses && v.T_world_camera_final ? *v.T_world_camera_final : v.result.T_world_camera;
}

// The map's first view, placed the same way.
StampedPose initialReference(const VisualFrameRecord& v, bool final_map_poses) {
  StampedPose first = *v.result.initial_reference;
  if (final_map_poses && v.initial_reference_final) first.T_world_frame = *v.initial_reference_final;
  return first;
}

// The visual pose carried into the odometry frame by its map's alignment,
// when the output may use it: a valid pose of an aligned map, and a LiDAR
// pose to rest on.
std::optional<Eigen::Isometry3d> visualInOdom(const VisualFrameRecord& v, bool final_map_poses, bool lidar_reliable) {
  const visual::VisualFrameResult& r = v.result;
  if (!r.pose_valid || !r.T_world_odom || !lidar_reliable) return std::nullopt;
  return r.T_world_odom->inverse() * visualPose(v, final_map_poses);
}

// The visual pose of a frame fused with the LiDAR's at its time, when the
// tracker gave its information (pose_fusion.h); both in the odometry frame.
std::optional<Eigen::Isometry3d> fusedWithLidar(const visual::VisualFrameResult& r,
                                                const Eigen::Isometry3d& T_odom_camera_visual,
                                                const Eigen::Isometry3d& T_odom_camera_lidar,
                                                const PoseFusionConfig& c, const OdometryPathLength& path) {
  if (!r.pose_information) return std::nullopt;
  const Matrix6d H_visual = decoupledInformation(*r.pose_information) / (c.visual_pixel_sigma * c.visual_pixel_sigma);
  const Matrix6d H_lidar = lidarPoseInformation(c, r.anchor_time ? path.since(*r.anchor_time) : 0.0);
  return fusePoses(T_odom_camera_visual.inverse(), H_visual, T_odom_camera_lidar.inverse(), H_lidar).inverse();
}

void lidarOutput(const PipelineRecords& records, const Eigen::Isometry3d& T_lidar_camera, SystemOutput& out) {
  if (records.lidar.empty()) {  // no camera: the LiDAR's own trajectory
    out.trajectory = records.T_odom_lidar_scans;
    out.trajectory_is_camera = false;
    return;
  }
  for (const LidarFrameRecord& l : records.lidar) {
    FrameOutput frame{l.t, std::nullopt, OutputSource::kLidar, "mode lidar"};
    if (l.T_odom_lidar) {
      frame.T_world_camera = *l.T_odom_lidar * T_lidar_camera;
      out.trajectory.push_back({l.t, *frame.T_world_camera});
    }
    out.frames.push_back(frame);
  }
}

// Visual mode: each new map starts where the last one ended (the camera is
// taken to have stood still while lost: no LiDAR to bridge the gap).
void visualOutput(const PipelineRecords& records, bool final_map_poses, SystemOutput& out) {
  OutputTrajectory output(Eigen::Isometry3d::Identity());  // no LiDAR: nothing to carry
  bool any_pose = false;
  for (const VisualFrameRecord& v : records.visual) {
    FrameOutput frame{v.t, std::nullopt, OutputSource::kVisual, ""};
    const auto& r = v.result;
    if (r.pose_valid) {
      if (r.initial_reference) {  // the map's first view, an earlier frame
        const StampedPose first = initialReference(v, final_map_poses);
        const Eigen::Isometry3d T =
            output.add({first.t, first.T_world_frame, r.map_id, std::nullopt}, OutputSource::kVisual);
        for (FrameOutput& earlier : out.frames)
          if (earlier.t == first.t) earlier.T_world_camera = T;
      }
      frame.T_world_camera =
          output.add({v.t, visualPose(v, final_map_poses), r.map_id, std::nullopt}, OutputSource::kVisual);
      out.metric = any_pose ? out.metric && r.metric : r.metric;
      any_pose = true;
    } else {
      frame.problem = "visual tracking " + std::string(visual::trackingStateName(r.state));
    }
    out.frames.push_back(frame);
  }
  out.trajectory = output.trajectory();
  out.T_world_map = output.mapPlacements();
}

// The paper's output: the visual pose while the detection module trusts
// it, the LiDAR's chained from the last output pose otherwise.
void visualFirstOutput(const PipelineRecords& records, const SystemConfig& config,
                       const Eigen::Isometry3d& T_lidar_camera, SystemOutput& out) {
  OutputTrajectory output(T_lidar_camera, RejoinStep{config.detection.rejoin_step_m, config.detection.rejoin_step_deg});
  DetectionModule detection(config.detection);
  for (std::size_t j = 0; j < records.visual.size(); ++j) {
    const VisualFrameRecord& v = records.visual[j];
    const LidarFrameRecord& l = records.lidar[j];
    const OutputSource source = detection.update(healthOf(v), frameDisagreement(records, j, T_lidar_camera));
    FrameOutput frame{v.t, std::nullopt, source, detection.lastProblem()};
    // Without any LiDAR pose yet nothing anchors the output world: skip.
    if (l.T_odom_lidar || !output.trajectory().empty()) {
      FrameEstimates estimates{v.t, std::nullopt, v.result.map_id, l.T_odom_lidar};
      if (v.result.pose_valid) estimates.T_map_camera = visualPose(v, config.final_map_poses);
      frame.T_world_camera = output.add(estimates, source);
    }
    out.frames.push_back(frame);
  }
  out.trajectory = output.trajectory();
  out.switches = detection.switches();
  out.T_world_map = output.mapPlacements();
}

// Output fusion (pose_fusion.h): the LiDAR pose, moved toward the fused one
// while the detection module trusts vision; world = the odometry frame.
void lidarFirstOutput(const PipelineRecords& records, const SystemConfig& config,
                      const Eigen::Isometry3d& T_lidar_camera, SystemOutput& out) {
  DetectionModule detection(config.detection);
  OutputCorrection correction(config.output_fusion.max_step_m, config.output_fusion.max_step_deg);
  OdometryPathLength path;
  std::vector<VisualDifference> differences;  // for the band-pass, one per output pose
  for (std::size_t j = 0; j < records.visual.size(); ++j) {
    const VisualFrameRecord& v = records.visual[j];
    const LidarFrameRecord& l = records.lidar[j];
    const OutputSource source = detection.update(healthOf(v), frameDisagreement(records, j, T_lidar_camera));
    FrameOutput frame{v.t, std::nullopt, source, detection.lastProblem()};
    if (v.result.T_world_odom) out.T_world_map[v.result.map_id] = v.result.T_world_odom->inverse();
    if (l.T_odom_lidar) {  // none before the LiDAR's first pose
      const Eigen::Isometry3d T_odom_camera_lidar = *l.T_odom_lidar * T_lidar_camera;
      path.add(v.t, T_odom_camera_lidar.translation());
      std::optional<Eigen::Isometry3d> visual, target;
      if (source == OutputSource::kVisual) visual = visualInOdom(v, config.final_map_poses, l.pose_reliable);
      if (visual) target = fusedWithLidar(v.result, *visual, T_odom_camera_lidar, config.output_fusion, path);
      frame.fused = target.has_value();
      Eigen::Isometry3d T_odom_camera = correction.add(T_odom_camera_lidar, target);
      VisualDifference difference{v.t, v.result.map_id, std::nullopt};
      if (visual) difference.d = visual->translation() - T_odom_camera.translation();
      differences.push_back(difference);
      frame.T_world_camera = T_odom_camera;
    }
    out.frames.push_back(frame);
  }
  // Vision's fast motion, filtered over the whole run (zero phase).
  const std::vector<Eigen::Vector3d> corrections = visualBandPass(differences, config.output_fusion.band_pass);
  for (FrameOutput& frame : out.frames) {  // those with a pose: one correction each, in order
    if (!frame.T_world_camera) continue;
    frame.T_world_camera->translation() += corrections[out.trajectory.size()];
    out.trajectory.push_back({frame.t, *frame.T_world_camera});
  }
  out.switches = detection.switches();
}

PlySegment coloured(const Eigen::Vector3d& a, const Eigen::Vector3d& b, unsigned char r, unsigned char g) {
  PlySegment s;
  s.a = a;
  s.b = b;
  s.r = r;
  s.g = g;
  s.b_colour = 0;
  return s;
}

void addLines(const PipelineRecords& records, SystemOutput& out) {
  for (std::size_t j = 0; j < records.lidar.size() && j < out.frames.size(); ++j) {
    const auto& T = out.frames[j].T_world_camera;
    if (!T) continue;
    for (const CameraLine& line : records.lidar[j].fusion_lines)
      out.lines_world.push_back(coloured(*T * line.A, *T * line.B, 255, 0));
  }
  for (const MapLine& line : records.visual_lines) {
    const auto placed = out.T_world_map.find(line.map_id);  // a map never placed in the output: its lines neither
    if (placed == out.T_world_map.end()) continue;
    const Eigen::Isometry3d& T_world_map = placed->second;
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
    if (r.initial_reference) map.push_back(initialReference(v, config.final_map_poses));
    map.push_back({v.t, visualPose(v, config.final_map_poses)});
  }
  if (config.mode != RunMode::kFused) return;
  for (const LidarFrameRecord& l : records.lidar)
    if (l.T_odom_lidar) out.lidar_camera.push_back({l.t, *l.T_odom_lidar * T_lidar_camera});
}

}  // namespace

VisualHealth healthOf(const VisualFrameRecord& record) {
  const visual::VisualFrameResult& r = record.result;
  VisualHealth h;
  h.t = record.t;
  h.state = stateOf(r.state);
  h.tracked_points = r.tracked_points;
  h.tracked_lines = r.tracked_lines;
  h.inlier_ratio = r.inlier_ratio;
  h.brightness = r.brightness;
  h.contrast = r.contrast;
  h.metric = !r.pose_valid || r.metric;
  return h;
}

SystemOutput assembleOutput(const PipelineRecords& records, const SystemConfig& config,
                            const Eigen::Isometry3d& T_camera_lidar) {
  SystemOutput out;
  const Eigen::Isometry3d T_lidar_camera = T_camera_lidar.inverse();
  switch (config.mode) {
    case RunMode::kLidar: lidarOutput(records, T_lidar_camera, out); break;
    case RunMode::kVisual: visualOutput(records, config.final_map_poses, out); break;
    case RunMode::kFused:
      if (config.output_fusion.enabled)
        lidarFirstOutput(records, config, T_lidar_camera, out);
      else
        visualFirstOutput(records, config, T_lidar_camera, out);
      break;
  }
  addLines(records, out);
  addSubsystemTrajectories(records, config, T_lidar_camera, out);
  return out;
}

}  // namespace lvslam::system
