#pragma once
// Monocular point-line visual SLAM (Structure PLP-SLAM / ORB-SLAM2 style, Cao
// et al. Sec. III-D): per image, features are extracted and the frame is
// tracked against the local map with a constant-velocity prediction; new
// keyframes run the local mapper in the same thread (deterministic). When
// tracking is lost it first retries against the old map from the last pose
// with a wide window, then starts a new map (new mapId()) and re-initialises,
// metric when depth hints are given. The maps given up are kept
// (retiredMaps()), each in its own world frame.
//
// Fusion face: setDepthHints() before track() for a metric start,
// lineSegments() of the current frame and addFusionLine() after track().
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/core/camera.h"
#include "lvslam/core/image_frame.h"
#include "lvslam/core/trajectory.h"
#include "lvslam/visual/data/visual_map.h"
#include "lvslam/visual/module/line_depth_check.h"
#include "lvslam/visual/module/map_culling.h"
#include "lvslam/visual/module/point_triangulation.h"
#include "lvslam/visual/tracking/extracted_image.h"
#include "lvslam/visual/tracking/frame_tracker.h"
#include "lvslam/visual/tracking/image_statistics.h"
#include "lvslam/visual/tracking/local_keyframes.h"
#include "lvslam/visual/tracking/map_initialization.h"
#include "lvslam/visual/visual_config.h"

namespace lvslam::visual {

enum class TrackingState { kInitializing, kTracking, kLost };
const char* trackingStateName(TrackingState state);

struct VisualSlamConfig {
  VisualConfig visual;
  ImageUsabilityConfig usability;
  int min_keypoints = 100;  // fewer: the frame is not usable (featureless, blurred)
  // Initialisation (ORB-SLAM): matches reference -> current in a window.
  double init_window_px = 100.0;
  int min_init_matches = 100;
  int max_init_frames = 30;     // a reference older than this is replaced
  double hint_radius_px = 3.0;  // a depth hint serves keypoints this close
  // A frame given hints of which too few reach keypoints is passed over as
  // the first view, at most this many times in a row.
  int max_unhinted_references = 10;
  // Tracking.
  double search_radius_px = 15.0;
  double refine_radius_px = 5.0;
  double recovery_radius_scale = 3.0;  // wider window after a failure / when lost
  int min_tracked = 30;                // point + line inliers
  // Lost: relocalisation into the old map for this many frames, then a new map.
  int relocalize_frames = 15;
  size_t relocalize_candidates = 4;  // covisible neighbours of the reference keyframe tried as pose guesses
  int relocalize_min_inliers = 50;   // point inliers to accept a relocalisation (ORB-SLAM: 50)
  int fusion_line_lifetime = 15;  // frames a fusion line waits for a keyframe observation
  size_t lidar_pose_buffer = 64;  // LiDAR poses kept for keyframes (> init window + LiDAR lag)
  PointTriangulationConfig triangulation;
  CullingConfig culling;
  LineDepthCheckConfig depth_check;
};

struct VisualFrameResult {
  double timestamp = 0.0;
  TrackingState state = TrackingState::kInitializing;
  bool pose_valid = false;  // tracked (or initialised) in this frame
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();  // world = the map's frame
  int map_id = 0;
  bool keyframe = false;
  bool metric = false;  // the map's scale came from depth hints
  // The map was initialised in this frame: its first view, at an earlier time
  // (keyframe initial_reference_keyframe).
  std::optional<StampedPose> initial_reference;
  int initial_reference_keyframe = -1;
  // Figures for the detection module.
  int tracked_points = 0, tracked_lines = 0;
  double inlier_ratio = 0.0;  // inliers / matches of the last pose optimisation
  double brightness = 0.0, contrast = 0.0;
  int keypoints = 0, segments = 0;
  // The map was pulled onto the LiDAR odometry in this frame
  // (config.visual.map_correction): earlier poses of this map are, in the
  // corrected map, T_new_old * T_world_camera (the newest keyframe's move).
  std::optional<Eigen::Isometry3d> T_new_old;
  // For the online estimator (system/online/fused_estimator.h): the
  // tracker's information on it (PoseOptimizationResult::information, at
  // 1 px per ORB level 0; none when the pose did not come from tracking),
  // and the map's alignment with the LiDAR odometry (VisualMap::T_world_odom).
  std::optional<Matrix6d> pose_information;
  std::optional<Eigen::Isometry3d> T_world_odom;
  // When the landmarks this pose rests on were mapped (medianFirstSeen of
  // its inlier points); with a pose_information only.
  std::optional<double> anchor_time;
  // The keyframe the frame was tracked against and the frame's pose relative
  // to it then (T_keyframe_camera), to place the frame on the map's final
  // keyframe poses (as ORB-SLAM's SaveTrajectoryTUM); -1 when none.
  int reference_keyframe = -1;
  Eigen::Isometry3d T_keyframe_camera = Eigen::Isometry3d::Identity();
  // The inliers the tracked pose rests on, to optimise it again against the
  // map's final landmarks (VisualSlam::relocateInFinalMap); empty when the
  // pose did not come from tracking.
  TrackedObservations observations;
};

class VisualSlam {
 public:
  VisualSlam(const VisualSlamConfig& config, const PinholeCamera& camera);
  ~VisualSlam();
  VisualSlam(const VisualSlam&) = delete;
  VisualSlam& operator=(const VisualSlam&) = delete;

  // Throws lvslam::Error on an image of the wrong size or type.
  VisualFrameResult track(const ImageFrame& frame);
  // The same for an image extracted elsewhere (extractImage with an extractor
  // built from config.visual.features and this camera).
  VisualFrameResult track(ExtractedImage image);

  // Hints for the next frame given to track(); used when that frame becomes
  // the first view of a map. Non-finite or non-positive depths are ignored.
  // Called at all (even with no hints), it marks the frame as one that should
  // have had hints: a frame whose hints reach too few keypoints is then not
  // taken as a first view (config.max_unhinted_references).
  void setDepthHints(std::vector<PixelDepth> hints);
  bool needsDepthHints() const;

  // The current frame's segments (index = segment index of addFusionLine).
  std::vector<ImageLineSegment> lineSegments() const;
  // A fusion line for segment `segment` of the current frame: endpoints A, B
  // and the direction d_fu in the current camera frame. It becomes a line
  // landmark with Plücker m = A x B, d = B - A moved to the world, flagged
  // from_fusion, with fusion_direction d_fu (or, when the segment already
  // tracks a landmark, that landmark gets d_fu). Returns the landmark id, or
  // -1 when the current frame has no pose. Throws lvslam::Error on non-finite
  // input, A == B or a segment index out of range.
  int addFusionLine(int segment, const Eigen::Vector3d& A_camera, const Eigen::Vector3d& B_camera,
                    const Eigen::Vector3d& direction_camera);

  // LiDAR depth of keyframe keypoints (DEMO / LIMO style), after track(): it
  // keeps the map at the LiDAR's metric scale through local BA depth terms.
  // The current frame's keypoints in raw (distorted) image pixels, index =
  // keypoint index.
  std::vector<Eigen::Vector2d> keypointPixels() const;
  // The current frame became a keyframe: only then are depths worth computing.
  bool currentIsKeyframe() const;
  // Camera-frame depth z per keypoint of the current frame, NaN (or any
  // non-finite / non-positive value) where none. Stored on the current
  // keyframe when the frame became one (and config.visual.use_keypoint_depths),
  // else ignored. Throws lvslam::Error when the size is not keypointPixels()'.
  void setKeypointDepths(const std::vector<double>& depths);

  // The LiDAR odometry's camera pose at time t (T_odom_camera: the camera in
  // the odometry's world), given in time order, typically a few frames late.
  // The latest config.lidar_pose_buffer are kept: a keyframe of the current
  // map at one of their times (now or later, as the initial pair's first
  // view) takes it as its prior in local BA (config.visual.
  // use_lidar_pose_priors; the first one aligns the odometry with the map).
  // Throws lvslam::Error when T is not a finite rigid transform.
  void addLidarPose(double t, const Eigen::Isometry3d& T_odom_camera);

  TrackingState state() const;
  int mapId() const;
  const VisualMap& map() const;  // the current map, id mapId()
  // The earlier maps, index = map id (retiredMaps().size() == mapId()).
  const std::vector<VisualMap>& retiredMaps() const;
  // The frame's pose T_world_camera in its map (result.map_id) as the map
  // stands now: result.observations optimised again from T_world_camera_initial
  // against the landmarks' current positions. None without observations, for
  // an unknown map, or when too few inliers remain.
  std::optional<Eigen::Isometry3d> relocateInFinalMap(const VisualFrameResult& result,
                                                      const Eigen::Isometry3d& T_world_camera_initial) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lvslam::visual
