#pragma once
// The visual subsystem's face: monocular point-line SLAM (PLP-SLAM / ORB-SLAM2
// style, Cao et al. Sec. III-D). Per image: extract, track the local map with
// a constant-velocity prediction, run the local mapper on new keyframes (same
// thread, deterministic). Lost: relocalise into the old map, then start a new
// map (mapId()), metric when depth hints are given; retired maps are kept.
// Settings: tracking/visual_slam_config.h; per-frame result:
// tracking/visual_frame_result.h; details: docs/visual-subsystem.md.
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/core/camera.h"
#include "lvslam/core/image_frame.h"
#include "lvslam/visual/data/visual_map.h"
#include "lvslam/visual/geometry/surface_depth.h"
#include "lvslam/visual/tracking/extracted_image.h"
#include "lvslam/visual/tracking/visual_frame_result.h"
#include "lvslam/visual/tracking/visual_slam_config.h"

namespace lvslam::visual {

class VisualSlam {
 public:
  VisualSlam(const VisualSlamConfig& config, const PinholeCamera& camera);
  ~VisualSlam();
  VisualSlam(const VisualSlam&) = delete;
  VisualSlam& operator=(const VisualSlam&) = delete;

  // One frame; throws lvslam::Error on an image of the wrong size or type.
  VisualFrameResult track(const ImageFrame& frame);
  // The same for an image extracted elsewhere (extractImage, same settings).
  VisualFrameResult track(ExtractedImage image);

  // Fusion face. Depth hints (raw pixels) for the next track(): a frame
  // whose keypoints read enough depths from them starts a map alone, else
  // they make a two-view start metric; calling it at all marks the frame as
  // one that needs hints (config.max_unhinted_references).
  void setDepthHints(std::vector<PixelDepth> hints);
  bool needsDepthHints() const;
  // The current frame's segments, index = `segment` of addFusionLine.
  std::vector<ImageLineSegment> lineSegments() const;
  // A fusion line (endpoints A, B, direction d_fu in the current camera) for
  // a segment: a new from_fusion landmark, or d_fu for the one it tracks.
  // Returns the landmark id, -1 without a pose; throws on bad input.
  int addFusionLine(int segment, const Eigen::Vector3d& A_camera, const Eigen::Vector3d& B_camera,
                    const Eigen::Vector3d& direction_camera);

  // LiDAR depth of keyframe keypoints (DEMO / LIMO style), after track():
  // raw pixels per keypoint; depths (non-finite / <= 0: none) are kept only
  // when the frame became a keyframe. Throws on a size mismatch.
  std::vector<Eigen::Vector2d> keypointPixels() const;
  bool currentIsKeyframe() const;
  void setKeypointDepths(const std::vector<double>& depths);

  // The LiDAR odometry's camera pose at t, in time order (a few frames late
  // is fine): a prior for keyframes at those times (config.visual.
  // use_lidar_pose_priors). Throws on a non-rigid or non-finite T.
  void addLidarPose(double t, const Eigen::Isometry3d& T_odom_camera);

  TrackingState state() const;
  int mapId() const;
  const VisualMap& map() const;  // the current map, id mapId()
  // The earlier maps, index = map id (retiredMaps().size() == mapId()).
  const std::vector<VisualMap>& retiredMaps() const;
  // After-run refinement: the frame's pose in its map as the map stands now
  // (result.replay.observations optimised again from T_world_camera_initial); none
  // without observations, for an unknown map or with too few inliers.
  std::optional<Eigen::Isometry3d> relocateInFinalMap(const VisualFrameResult& result,
                                                      const Eigen::Isometry3d& T_world_camera_initial) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lvslam::visual
