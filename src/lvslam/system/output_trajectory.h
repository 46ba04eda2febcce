#pragma once
// The system's output: T_world_camera at every camera time, continuous across
// switches between the visual and the LiDAR odometry. In LiDAR mode the
// LiDAR's motion, carried into the camera frame through the extrinsics, is
// chained from the last output pose; back in visual mode the visual map
// (possibly a new one after re-initialization) is re-anchored at the current
// output pose, so the trajectory has no jump at a switch. Back in a map it
// was anchored in before, the output then rejoins that map's first anchor by
// bounded steps per frame: otherwise every excursion to the LiDAR (a visual
// glitch is enough) would leave its offset in the output for good.
#include <map>
#include <optional>

#include <Eigen/Geometry>

#include "lvslam/core/trajectory.h"
#include "lvslam/system/detection/detection_module.h"

namespace lvslam::system {

struct FrameEstimates {
  double t = 0.0;
  std::optional<Eigen::Isometry3d> T_map_camera;  // visual estimate in its map frame
  int visual_map_id = 0;                          // changes when vision re-initializes
  std::optional<Eigen::Isometry3d> T_odom_lidar;  // LiDAR odometry at the camera time
};

// How fast the output rejoins a visual map's first anchor: the camera moves
// at most this much per frame beyond the map's own motion (0: never rejoins).
struct RejoinStep {
  double max_m = 0.0;
  double max_deg = 0.0;
};

class OutputTrajectory {
 public:
  explicit OutputTrajectory(const Eigen::Isometry3d& T_lidar_camera, const RejoinStep& rejoin = {})
      : T_lidar_camera_(T_lidar_camera), rejoin_(rejoin) {}

  // Appends and returns the output pose of this frame.
  Eigen::Isometry3d add(const FrameEstimates& frame, OutputSource source);

  const Trajectory& trajectory() const { return trajectory_; }
  // Where each visual map anchored so far sits in the output world (its
  // first anchor, which the output rejoins): T_world_map per map id.
  std::map<int, Eigen::Isometry3d> mapPlacements() const;

 private:
  struct Anchor {
    Eigen::Isometry3d first;    // T_world_map when the map was first anchored
    Eigen::Isometry3d current;  // in use: the last re-anchoring, moving back to `first`
  };
  std::optional<Eigen::Isometry3d> lidarIncrement(const FrameEstimates& frame) const;
  void stepTowardFirst(Anchor& anchor, const Eigen::Isometry3d& T_map_camera) const;

  Eigen::Isometry3d T_lidar_camera_;
  RejoinStep rejoin_;
  Trajectory trajectory_;
  std::optional<Eigen::Isometry3d> last_T_odom_lidar_;
  std::map<int, Anchor> anchors_;  // per visual map id
  int anchored_map_id_ = -1;                   // the map anchored last
  OutputSource last_source_ = OutputSource::kLidar;
};

}  // namespace lvslam::system
