#include "lvslam/system/online/online_output.h"

#include <utility>

#include "lvslam/system/final_visual_poses.h"
#include "lvslam/system/online/pose_information.h"
#include "lvslam/system/output_trajectory.h"

namespace lvslam::system {

namespace {

// A frame's output before any pose is known.
FrameOutput frameAt(double t, OutputSource source, std::string problem) {
  FrameOutput frame;
  frame.t = t;
  frame.source = source;
  frame.problem = std::move(problem);
  return frame;
}

VisualState stateOf(visual::TrackingState state) {
  switch (state) {
    case visual::TrackingState::kTracking: return VisualState::kTracking;
    case visual::TrackingState::kLost: return VisualState::kLost;
    case visual::TrackingState::kInitializing: break;
  }
  return VisualState::kInitializing;
}

class LidarOnline final : public OnlineOutput {
 public:
  explicit LidarOnline(const Eigen::Isometry3d& T_lidar_camera) : T_lidar_camera_(T_lidar_camera) {}
  FrameOutput add(const VisualFrameRecord*, const LidarFrameRecord* l) override {
    FrameOutput frame = frameAt(l->t, OutputSource::kLidar, "mode lidar");
    if (l->T_odom_lidar) frame.T_world_camera = *l->T_odom_lidar * T_lidar_camera_;
    return frame;
  }

 private:
  Eigen::Isometry3d T_lidar_camera_;
};

// Visual mode: each new map starts where the last one ended (no LiDAR to
// bridge a loss: the camera is taken to have stood still).
class VisualOnline final : public OnlineOutput {
 public:
  explicit VisualOnline(bool final_poses) : output_(Eigen::Isometry3d::Identity()), final_poses_(final_poses) {}
  FrameOutput add(const VisualFrameRecord* v, const LidarFrameRecord*) override {
    FrameOutput frame = frameAt(v->t, OutputSource::kVisual, "");
    const auto& r = v->result;
    if (!r.pose_valid) {
      frame.problem = "visual tracking " + std::string(visual::trackingStateName(r.state));
      return frame;
    }
    // The map's first view is an earlier frame whose output is already out:
    // it anchors the map, it is not output again.
    if (r.initial_reference) {
      const StampedPose first = initialReferenceOf(*v, final_poses_);
      output_.add({first.t, first.T_world_frame, r.map_id, std::nullopt}, OutputSource::kVisual);
    }
    frame.T_world_camera = output_.add({v->t, visualPoseOf(*v, final_poses_), r.map_id, std::nullopt}, OutputSource::kVisual);
    return frame;
  }
  std::map<int, Eigen::Isometry3d> mapPlacements() const override { return output_.mapPlacements(); }

 private:
  OutputTrajectory output_;
  bool final_poses_;
};

// The paper's output: the visual pose while the detection module trusts
// it, the LiDAR's motion chained from the last output pose otherwise.
class PaperOnline final : public OnlineOutput {
 public:
  PaperOnline(const SystemConfig& config, const Eigen::Isometry3d& T_lidar_camera, bool final_poses)
      : output_(T_lidar_camera, RejoinStep{config.detection.rejoin_step_m, config.detection.rejoin_step_deg}),
        detection_(config.detection), final_poses_(final_poses) {}
  FrameOutput add(const VisualFrameRecord* v, const LidarFrameRecord* l) override {
    const OutputSource source = detection_.update(healthOf(*v));
    FrameOutput frame = frameAt(v->t, source, detection_.lastProblem());
    // Without any LiDAR pose yet nothing anchors the output world.
    if (l->T_odom_lidar || !output_.trajectory().empty()) {
      FrameEstimates estimates{v->t, std::nullopt, v->result.map_id, l->T_odom_lidar};
      if (v->result.pose_valid) estimates.T_map_camera = visualPoseOf(*v, final_poses_);
      frame.T_world_camera = output_.add(estimates, source);
    }
    return frame;
  }
  std::vector<SwitchEvent> switches() const override { return detection_.switches(); }
  std::map<int, Eigen::Isometry3d> mapPlacements() const override { return output_.mapPlacements(); }

 private:
  OutputTrajectory output_;
  DetectionModule detection_;
  bool final_poses_;
};

// Fused mode: the detection module admits vision by its health, the LiDAR
// by its registration; the estimator weighs what is admitted.
class FusedOnline final : public OnlineOutput {
 public:
  FusedOnline(const SystemConfig& config, const Eigen::Isometry3d& T_camera_lidar)
      : estimator_(config.estimator), detection_(config.detection), T_camera_lidar_(T_camera_lidar) {}

  FrameOutput add(const VisualFrameRecord* v, const LidarFrameRecord* l) override {
    const OutputSource admitted = detection_.update(healthOf(*v));
    FrameOutput frame = frameAt(v->t, OutputSource::kLidar, detection_.lastProblem());
    std::optional<VisualFrameInput> visual;
    if (admitted == OutputSource::kVisual) visual = visualInput(v->result);
    const FusedFrameOutput out = estimator_.add(v->t, lidarInput(*l), visual);
    camera_nodes_.push_back(out.camera_node);
    if (v->result.fusion.T_world_odom) placements_[v->result.map_id] = v->result.fusion.T_world_odom->inverse();
    frame.T_world_camera = out.T_world_camera;
    if (out.visual_used) frame.source = OutputSource::kVisual;
    frame.fused = out.visual_used && out.lidar_used;
    frame.gated = out.gated;
    frame.visual_chi_square_per_dof = out.visual_chi_square_per_dof;
    frame.lidar_noise_scale = out.lidar_noise_scale;
    frame.visual_noise_scale = out.visual_noise_scale;
    frame.covariance = out.covariance;
    return frame;
  }
  void lidarImproved(std::size_t index, const LidarFrameRecord& l) override {
    const std::optional<LidarFrameInput> lidar = lidarInput(l);
    if (index < camera_nodes_.size() && camera_nodes_[index] >= 0 && lidar)
      estimator_.improveLidar(camera_nodes_[index], *lidar);
  }
  std::vector<SwitchEvent> switches() const override { return detection_.switches(); }
  std::map<int, Eigen::Isometry3d> mapPlacements() const override { return placements_; }
  std::optional<EstimatorGraph> takeGraph() override { return estimator_.takeGraph(); }

 private:
  // A LiDAR pose the registration stood behind: scans registered on both
  // sides of the frame with information in some direction.
  std::optional<LidarFrameInput> lidarInput(const LidarFrameRecord& l) const {
    if (!l.T_odom_lidar || !l.pose_reliable || l.information.isZero()) return std::nullopt;
    return LidarFrameInput{*l.T_odom_lidar * T_camera_lidar_.inverse(),
                           lidarToCameraInformation(l.information, T_camera_lidar_), l.degenerate, l.registration};
  }

  // The frame's visual pose in its map as tracked, with the map's
  // corrections since the last frame.
  static std::optional<VisualFrameInput> visualInput(const visual::VisualFrameResult& r) {
    if (!r.pose_valid || !r.fusion.pose_information) return std::nullopt;
    VisualFrameInput in;
    in.map_id = r.map_id;
    in.T_map_camera = r.T_world_camera;
    in.information = *r.fusion.pose_information;
    in.T_new_old = r.fusion.T_new_old;
    in.initial_view = r.initial_reference;
    return in;
  }

  FusedEstimator estimator_;
  DetectionModule detection_;
  Eigen::Isometry3d T_camera_lidar_;
  std::map<int, Eigen::Isometry3d> placements_;
  std::vector<int> camera_nodes_;  // per frame, the estimator's node (-1: none)
};

}  // namespace

VisualHealth healthOf(const VisualFrameRecord& record) {
  const visual::VisualFrameResult& r = record.result;
  VisualHealth h;
  h.t = record.t;
  h.state = stateOf(r.state);
  h.tracked_points = r.health.tracked_points;
  h.tracked_lines = r.health.tracked_lines;
  h.inlier_ratio = r.health.inlier_ratio;
  h.brightness = r.health.brightness;
  h.contrast = r.health.contrast;
  h.metric = !r.pose_valid || r.metric;
  return h;
}

std::unique_ptr<OnlineOutput> makeOnlineOutput(const SystemConfig& config, const Eigen::Isometry3d& T_camera_lidar,
                                               bool final_visual_poses) {
  switch (config.mode) {
    case RunMode::kLidar: return std::make_unique<LidarOnline>(T_camera_lidar.inverse());
    case RunMode::kVisual: return std::make_unique<VisualOnline>(final_visual_poses);
    case RunMode::kFused: break;
  }
  if (config.paper_output) return std::make_unique<PaperOnline>(config, T_camera_lidar.inverse(), final_visual_poses);
  return std::make_unique<FusedOnline>(config, T_camera_lidar);
}

}  // namespace lvslam::system
