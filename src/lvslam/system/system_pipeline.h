#pragma once
// Runs the subsystems of a mode over a recording (paper, Fig. 1): in fused
// mode the LiDAR thread (LiDAR subsystem + fusion framework) and the visual
// thread exchange, per camera frame, the image's line segments and the
// fusion lines; bounded queues carry the sensor data to both. The order of
// every computation is fixed by the data, so the threaded run gives the same
// numbers as the one-thread deterministic run.
#include <chrono>
#include <functional>
#include <map>
#include <optional>
#include <vector>

#include "lvslam/core/error.h"
#include "lvslam/fusion/extrinsic_check.h"
#include "lvslam/io/ply_writer.h"
#include "lvslam/io/sensor_source.h"
#include "lvslam/loop/loop_closure.h"
#include "lvslam/system/frame_records.h"
#include "lvslam/system/record_fields.h"
#include "lvslam/system/record_file.h"
#include "lvslam/system/online/online_output.h"
#include "lvslam/system/system_config.h"

namespace lvslam::system {

// A 3D line of a visual map, in that map's frame.
struct MapLine {
  Eigen::Vector3d start = Eigen::Vector3d::Zero(), end = Eigen::Vector3d::Zero();
  bool from_fusion = false;
  int map_id = 0;
  std::optional<double> first_seen;  // its first keyframe's time: loop closure moves it with the map of that time
};

struct PipelineRecords {
  // When the last online pose was out (the run's online part ends here;
  // the loop closure's last solve and the refinement come after).
  std::chrono::steady_clock::time_point online_end;
  // On disk (record_file.h): read them in order, each read is a copy.
  RecordFile<VisualFrameRecord> visual;  // one per camera frame (visual and fused modes)
  RecordFile<LidarFrameRecord> lidar;    // one per camera frame (lidar and fused modes)
  RecordFile<ScanRecord> scans;
  Trajectory T_odom_lidar_scans;          // at scan times
  std::vector<PlyPoint> lidar_map;        // odometry world frame
  // Loop closure over the LiDAR keyframes (loop.enabled, lidar and fused
  // modes), and per keyframe the first lidar_map point added from its scan on.
  std::optional<loop::LoopClosureResult> loop;
  std::vector<loop::LoopKeyframe> loop_keyframes;  // their odometry poses and features (a saved map's)
  std::vector<std::size_t> lidar_map_keyframe_starts;
  std::vector<MapLine> visual_lines;      // the lines of every visual map, old and current
  // Fused mode: the extrinsic check's verdict per window of frames.
  std::vector<fusion::ExtrinsicVerdict> extrinsic_checks;
  // The online output, one per camera frame, each made when its data were in
  // (online/online_output.h), with the detection module's switches and where
  // each visual map sat in the output world.
  RecordFile<FrameOutput> online;
  // Fused mode: the online estimator's graph over the whole run, for the
  // offline refinement.
  std::optional<EstimatorGraph> estimator_graph;
  std::vector<SwitchEvent> switches;
  std::map<int, Eigen::Isometry3d> T_world_map;
  std::size_t images = 0, scans_read = 0;  // as read from the source
  double first_time = 0.0, last_time = 0.0;  // of the sensor data
  // Why the source could not be read further (a truncated last scan or PNG,
  // what a killed recorder leaves): the run stopped there and these records
  // hold everything up to it. None when the whole recording was read.
  std::optional<Error> input_fault;
};

// Called by the reading thread after each item handed on (time of the item,
// images and scans so far).
using ProgressCallback = std::function<void(double t, std::size_t images, std::size_t scans)>;

// Bad input the source reports (lvslam::Error from next()) ends the reading
// there: the subsystems finish what was read and the records say where it
// stopped (input_fault). Any other failure (either subsystem) throws, after
// both threads have stopped.
// `on_frame` gets each frame's online output as it is made (frame order).
using FrameOutputCallback = std::function<void(const FrameOutput&)>;
PipelineRecords runPipeline(SensorSource& source, const SystemConfig& config, const ProgressCallback& progress,
                            const FrameOutputCallback& on_frame = {});

}  // namespace lvslam::system
