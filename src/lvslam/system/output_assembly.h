#pragma once
// The system's output from the subsystems' per-frame records, frame by frame
// in time order (each decision uses only that frame and earlier ones, as an
// online system would): the detection module decides whether vision is
// trusted. Fused mode with output fusion: the LiDAR pose, corrected toward
// the visual and LiDAR poses' fusion while it is (OutputCorrection);
// the paper's output and visual mode: OutputTrajectory keeps the chosen
// odometry continuous across switches.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lvslam/core/trajectory.h"
#include "lvslam/io/ply_writer.h"
#include "lvslam/system/detection_module.h"
#include "lvslam/system/system_config.h"
#include "lvslam/system/system_pipeline.h"

namespace lvslam::system {

struct FrameOutput {
  double t = 0.0;
  std::optional<Eigen::Isometry3d> T_world_camera;  // none: no estimate for this frame
  OutputSource source = OutputSource::kLidar;
  std::string problem;  // the detection module's reason when vision was not used
  bool fused = false;   // the visual pose fused with the LiDAR's (SystemConfig::output_fusion)
};

struct SystemOutput {
  // T_world_camera per camera frame with an estimate; T_world_lidar per scan
  // when the recording has no camera (lidar mode only).
  Trajectory trajectory;
  bool trajectory_is_camera = true;
  bool metric = true;  // false: a monocular visual run without LiDAR depth
  std::vector<FrameOutput> frames;  // per camera frame
  std::vector<SwitchEvent> switches;
  // Where each visual map that reached the output sits in its world.
  std::map<int, Eigen::Isometry3d> T_world_map;
  std::vector<PlySegment> lines_world;  // fusion lines (red) and the visual map's lines (green; orange from fusion)
  // Each subsystem's own estimate, before the detection module chose: the
  // visual subsystem's T_map_camera per map id (in that map's frame), and the
  // LiDAR odometry carried to the camera (T_odom_camera, fused mode).
  std::map<int, Trajectory> visual_maps;
  Trajectory lidar_camera;
};

SystemOutput assembleOutput(const PipelineRecords& records, const SystemConfig& config,
                            const Eigen::Isometry3d& T_camera_lidar);

// Health figures of one visual frame for the detection module.
VisualHealth healthOf(const VisualFrameRecord& record);

}  // namespace lvslam::system
