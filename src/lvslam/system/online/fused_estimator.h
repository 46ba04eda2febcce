#pragma once
// The online estimator of fused mode: one causal T_world_camera per camera
// frame from both subsystems, each weighted by its own uncertainty, never
// revised once emitted. A fixed-lag window (window_s) of frame poses is
// solved per frame (pose_graph.h) with relative-pose factors:
//  - LiDAR: the odometry's camera pose through the odometry frame's own
//    node (T_world_odom, one per frame with a LiDAR pose), its covariance
//    from the ICP's normal equations (a degenerate direction gets no
//    information); consecutive odometry-frame nodes are tied by the
//    odometry's drift per metre of path (a random walk about the camera),
//    so scan-to-map registration errors stay white and only drift accumulates;
//    a degenerate registration (blind along some direction) does not hold
//    the odometry to its map, and walks its frame by its own covariance;
//  - visual: the tracker's camera pose in its map, through the map's own
//    node (T_world_map, one per frame with a visual pose), its information
//    from the tracker's Hessian (the pose against the map's landmarks, so
//    re-observing an old part of the map measures the pose in that map);
//    consecutive map nodes are tied by the map's drift per metre of path,
//    exactly as the LiDAR's odometry frame is, and carry the map's own
//    corrections (T_new_old);
//  - motion: constant velocity with the robot's acceleration as noise, the
//    process model that keeps the graph connected and breaks ties.
// Each subsystem's new pose is first judged against its own previous steps
// (step_gate.h): a jump its stated uncertainty cannot explain is dropped and
// logged. A lasting disagreement between the two subsystems is not a jump:
// it is weighed, and reported by the visual factors' chi-square.
// World = the LiDAR odometry frame at the first LiDAR pose.
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lvslam/core/trajectory.h"
#include "lvslam/system/online/pose_graph.h"
#include "lvslam/system/online/step_gate.h"
#include "lvslam/system/record_file.h"

namespace lvslam::system {

struct FusedEstimatorConfig {
  double window_s = 1.5;           // seconds of frames optimised together
  double visual_pixel_sigma = 3.0;  // the tracker's information is at 1 px (ORB level 0)
  double lidar_drift_m = 0.005;     // odometry error growth per sqrt(m) of path (random walk)
  double lidar_drift_deg = 0.03;
  double visual_drift_m = 0.02;     // the visual map's error growth per sqrt(m) of path
  double visual_drift_deg = 0.12;
  double motion_accel = 2.0;           // m/s^2 (1 sigma): the platform's acceleration
  double motion_angular_accel_deg = 90.0;  // deg/s^2
  int gate_accept_after = 3;  // gated steps in a row before a jump counts as a new start
  // Seconds of nodes and factors kept behind the newest frame (more than
  // window_s), so that online memory does not grow with the run; < 0 keeps
  // the whole run's graph (the offline refinement's replay).
  double history_s = 30.0;
  double huber_delta = 3.0;
  int max_iterations = 8;
};

// The LiDAR's view of one camera frame (already judged healthy).
struct LidarFrameInput {
  Eigen::Isometry3d T_odom_camera = Eigen::Isometry3d::Identity();
  // Of T_odom_camera, camera-frame right perturbation; zero where degenerate.
  Matrix6d information = Matrix6d::Zero();
  // The registration was blind along some direction: scan-to-map did not
  // hold the odometry to its map, which then walks like frame-to-frame
  // odometry, by each new registration's own error.
  bool degenerate = false;
  std::size_t registration = 0;  // which registered scan the pose comes from
};

// The visual subsystem's view of one camera frame (admitted by the
// detection module). Poses in the map's frame as it stands at this frame.
struct VisualFrameInput {
  int map_id = 0;
  Eigen::Isometry3d T_map_camera = Eigen::Isometry3d::Identity();
  Matrix6d information = Matrix6d::Zero();  // the tracker's, at 1 px (left update of T_camera_map)
  // The map was corrected in this frame: earlier poses in it are T_new_old * T.
  std::optional<Eigen::Isometry3d> T_new_old;
  // The map was initialised in this frame: its first view (an earlier frame) in it.
  std::optional<StampedPose> initial_view;
};

struct FusedFrameOutput {
  std::optional<Eigen::Isometry3d> T_world_camera;  // none before the first LiDAR pose
  int camera_node = -1;                             // the frame's node in the graph
  // Each subsystem's covariance multiplier, from its own steps (step_gate.h).
  double lidar_noise_scale = 1.0, visual_noise_scale = 1.0;
  bool lidar_used = false, visual_used = false;     // factors of this frame in the graph
  std::vector<GateEvent> gated;
  double visual_chi_square_per_dof = -1.0;  // of the accepted visual factor at the solution, -1: none
  // Of T_world_camera in the window (older nodes held): world-frame
  // translation, then world-frame rotation (pose_graph.h, NodeCovariance).
  std::optional<Matrix6d> covariance;
};

// A node as the estimator let it go: its time, its last estimate (it has
// left the window's reach) and whether it is a camera frame's (the others
// are odometry-frame and map nodes).
struct RetiredNode {
  double t = 0.0;
  PoseNode node;
  bool camera = false;
};
template <typename A>
void fields(A& a, RetiredNode& n) {
  static_assert(sizeof(RetiredNode) == 176, "RetiredNode changed: list its fields here");
  a(n.t), a(n.node), a(n.camera);
}

// Every node in id order (time, last estimate), the camera frames' node
// ids in frame order, and every accepted factor.
struct EstimatorGraph {
  std::vector<double> times;
  std::vector<PoseNode> nodes;
  std::vector<int> camera_nodes;
  RecordFile<PoseFactor> factors;
};

class FusedEstimator {
 public:
  explicit FusedEstimator(const FusedEstimatorConfig& config);

  FusedFrameOutput add(double t, const std::optional<LidarFrameInput>& lidar,
                       const std::optional<VisualFrameInput>& visual);
  // A better LiDAR pose of an added frame (interpolated once the next sweep
  // was registered): replaces its LiDAR factor's measurement. The frame's
  // output stays what it was; the window's later frames gain.
  void improveLidar(int camera_node, const LidarFrameInput& lidar);

  // The whole run's graph (what the offline refinement smooths): the part
  // the history let go, kept on disk as it went (record_file.h), then the
  // part it holds. Moves the disk part out: call it once, at the end.
  EstimatorGraph takeGraph();
  // Nodes held in memory (history_s of them; the rest went to disk).
  std::size_t nodesHeld() const { return nodes_.size(); }

 private:
  struct Candidate {
    PoseFactor factor;
    Eigen::Isometry3d T_world_implied;  // the new node's pose the factor implies
    int rank = 0;                       // directions its information knows
  };
  int addNode(double t, const Eigen::Isometry3d& T, bool fixed);
  void accept(const PoseFactor& factor);
  std::optional<Candidate> lidarFactor(int node, const LidarFrameInput& lidar, bool new_start);
  // Keeps the map's corrections; the factor only when `use`. The
  // information is already weighed (pixel sigma, the gate's noise scale).
  std::optional<Candidate> visualFactor(int node, const VisualFrameInput& visual, bool use, bool new_start);
  Candidate motionFactor(int node, double t) const;
  Candidate makeCandidate(PoseFactor factor) const;
  // Solves the window ending at `newest`; the covariance of node `of`.
  std::optional<Matrix6d> solveWindow(int newest, int of);
  std::optional<int> cameraNodeAt(double t) const;
  double chiSquare(const PoseFactor& factor) const;  // at the nodes' latest estimates
  void forget(double t_newest);
  // Node and factor ids count from the run's start; the stored ones begin
  // at first_node_ and first_factor_ (forget()).
  PoseNode& nodeAt(int id) { return nodes_[static_cast<std::size_t>(id - first_node_)]; }
  const PoseNode& nodeAt(int id) const { return nodes_[static_cast<std::size_t>(id - first_node_)]; }
  double timeOf(int id) const { return times_[static_cast<std::size_t>(id - first_node_)]; }
  std::vector<int>& factorsTo(int id) { return factors_to_[static_cast<std::size_t>(id - first_node_)]; }
  PoseFactor& factorAt(int id) { return factors_[static_cast<std::size_t>(id - first_factor_)]; }

  FusedEstimatorConfig config_;
  StepGate lidar_gate_, visual_gate_;
  int visual_map_ = -1;  // the map the visual gate's history is in
  int first_node_ = 0, first_factor_ = 0;
  std::vector<double> times_;
  std::vector<PoseNode> nodes_;
  std::vector<PoseFactor> factors_;
  std::vector<std::vector<int>> factors_to_;  // per node, the accepted factors ending at it
  std::vector<int> camera_nodes_;             // in frame order
  // What forget() let go, in id order.
  RecordFile<RetiredNode> retired_nodes_;
  RecordFile<PoseFactor> retired_factors_;
  // The odometry-frame node of the last LiDAR pose, and that pose.
  std::optional<std::pair<int, LidarFrameInput>> last_lidar_;
  std::size_t last_walk_registration_ = 0;  // the last degenerate registration its frame walked by
  // Per visual map: its node at the last visual pose, that pose, and the
  // map's corrections since (p_new = T_new_old p_old).
  struct LastVisual {
    int map_node = -1;
    Eigen::Isometry3d T_map_camera = Eigen::Isometry3d::Identity();
    Eigen::Isometry3d T_new_old = Eigen::Isometry3d::Identity();
  };
  std::map<int, LastVisual> last_visual_;
};

}  // namespace lvslam::system
