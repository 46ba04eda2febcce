#pragma once
// The system's outputs after a run: the online trajectory as it was made
// frame by frame (PipelineRecords::online), the offline refinement
// (offline/refinement.h), the lines of the maps in the output world, and
// each subsystem's own estimate.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lvslam/core/trajectory.h"
#include "lvslam/io/ply_writer.h"
#include "lvslam/system/detection/detection_module.h"
#include "lvslam/system/system_config.h"
#include "lvslam/system/system_pipeline.h"

namespace lvslam::system {

struct SystemOutput {
  // The online output: T_world_camera per camera frame with an estimate;
  // T_world_lidar per scan when the recording has no camera (lidar mode).
  Trajectory trajectory;
  // The offline refinement of the same frames (same frame as `trajectory`).
  Trajectory trajectory_refined;
  bool trajectory_is_camera = true;
  bool metric = true;  // false: a monocular visual run without LiDAR depth
  std::vector<SwitchEvent> switches;
  // Where each visual map that reached the output sits in its world.
  std::map<int, Eigen::Isometry3d> T_world_map;
  // The loop closure as applied to trajectory_refined, map.ply and the
  // lines (refinement.h); none without loop closure.
  std::optional<loop::LoopClosureResult> loop;
  // The LiDAR map (odometry frame), each point moved with its keyframe's
  // loop correction when loops were closed.
  std::vector<PlyPoint> lidar_map;
  std::vector<PlySegment> lines_world;  // fusion lines (red) and the visual map's lines (green; orange from fusion)
  // The online poses placed in a saved map once the run was localised in it
  // (--map-in; an offline placement: the frames before the localising
  // keyframe get it afterwards); empty otherwise.
  Trajectory trajectory_in_map;
  // Each subsystem's own estimate, before the detection module chose: the
  // visual subsystem's T_map_camera per map id (in that map's frame, on the
  // final keyframes when system.final_map_poses), and the LiDAR odometry
  // carried to the camera (T_odom_camera, fused mode).
  std::map<int, Trajectory> visual_maps;
  Trajectory lidar_camera;
};

SystemOutput assembleOutput(const PipelineRecords& records, const SystemConfig& config,
                            const Eigen::Isometry3d& T_camera_lidar);

}  // namespace lvslam::system
