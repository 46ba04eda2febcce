#include "lvslam/visual/visual_slam.h"

#include <algorithm>
#include <cmath>
#include <deque>

#include "lvslam/core/error.h"
#include "lvslam/core/se3.h"
#include "lvslam/visual/feature/feature_extractor.h"
#include "lvslam/visual/geometry/surface_depth.h"
#include "lvslam/visual/module/local_mapper.h"
#include "lvslam/visual/optimize/solver_logging.h"
#include "lvslam/visual/tracking/frame_tracker.h"
#include "lvslam/visual/tracking/keyframe_policy.h"
#include "lvslam/visual/tracking/local_keyframes.h"
#include "lvslam/visual/tracking/map_initialization.h"
#include "lvslam/visual/tracking/motion_model.h"
#include "lvslam/visual/tracking/relocalization.h"

namespace lvslam::visual {

const char* trackingStateName(TrackingState state) {
  switch (state) {
    case TrackingState::kInitializing: return "initializing";
    case TrackingState::kTracking: return "tracking";
    case TrackingState::kLost: return "lost";
  }
  return "unknown";
}

namespace {

// The landmark ids a frame's feature table observes (-1: none), in feature order.
std::vector<int> observedLandmarks(const std::vector<int>& table) {
  std::vector<int> ids;
  for (const int id : table)
    if (id >= 0) ids.push_back(id);
  return ids;
}

double inlierRatio(int point_inliers, int line_inliers, int matches) {
  return static_cast<double>(point_inliers + line_inliers) / std::max(1, matches);
}

FrameTrackerConfig trackerConfig(const VisualSlamConfig& c) {
  FrameTrackerConfig t;
  t.search_radius_px = c.search_radius_px;
  t.refine_radius_px = c.refine_radius_px;
  t.min_inliers = c.min_tracked;
  t.point_matching = c.modules.point_matching;
  t.point_matching.max_distance = c.track_max_distance;
  t.line_matching = c.modules.line_matching;
  t.pose = c.modules.pose;
  return t;
}

LocalMapperConfig mapperConfig(const VisualSlamConfig& c) {
  LocalMapperConfig m;
  m.points = c.triangulation;
  m.line_matching = c.modules.line_matching;
  m.window = c.modules.local_window;
  m.culling = c.culling;
  m.depth_check = c.depth_check;
  return m;
}

// Keypoints in raw image pixels, where depth hints and keypoint depths are given.
std::vector<Eigen::Vector2d> rawKeypointPixels(const FeatureFrame& features) {
  std::vector<Eigen::Vector2d> pixels;
  pixels.reserve(features.keypoints.size());
  for (const cv::KeyPoint& k : features.keypoints) pixels.emplace_back(k.pt.x, k.pt.y);
  return pixels;
}

PinholeIntrinsics intrinsicsOf(const PinholeCamera& camera) {
  return {camera.fx(), camera.fy(), camera.cx(), camera.cy()};
}

}  // namespace

struct VisualSlam::Impl {
  Impl(const VisualSlamConfig& c, const PinholeCamera& cam)
      : config(c),
        camera(cam),
        K(intrinsicsOf(cam)),
        extractor(c.modules.features, cam),
        initializer(c.modules.initializer, K),
        tracker(trackerConfig(c)),
        mapper(mapperConfig(c), K) {}

  struct FusionLineWait {
    int line = -1, until_frame = 0;
  };

  VisualSlamConfig config;
  PinholeCamera camera;
  PinholeIntrinsics K;
  FeatureExtractor extractor;
  TwoViewInitializer initializer;
  FrameTrackerConfig tracker;
  LocalMapper mapper;

  VisualMap map;
  int map_id = 0;
  std::vector<VisualMap> retired_maps;  // index = map id: the maps given up after a loss
  TrackingState state = TrackingState::kInitializing;
  int frame_index = -1;
  TrackedFrame current;
  bool current_has_pose = false;
  int current_keyframe = -1;  // the current frame's keyframe id, -1 if none
  std::vector<PixelDepth> next_hints;
  bool next_hints_given = false;
  bool hints_given = false;  // setDepthHints() was called for the current frame
  // Initialisation reference.
  std::optional<TrackedFrame> reference;
  double reference_time = 0.0;
  int reference_frame = 0;
  std::vector<double> reference_depths;  // per keypoint of the reference, NaN: none
  int skipped_references = 0;
  bool metric = false;
  // Tracking.
  Eigen::Isometry3d T_last = Eigen::Isometry3d::Identity();  // T_camera_world of the last tracked frame
  ConstantVelocity motion;  // velocity = T_last * T_before^-1
  double last_time = 0.0;   // of T_last
  int reference_keyframe = -1;
  int last_keyframe_frame = 0;
  int reference_tracked_keyframe = -1, reference_tracked_points = 0;  // points tracked when it was inserted
  int lost_frames = 0;
  std::vector<FusionLineWait> fusion_lines;
  std::vector<int> last_points;  // landmarks the last tracked frame observed
  std::deque<StampedPose> lidar_poses;  // the latest addLidarPose() poses (T_odom_camera)
  int keyframes_since_correction = 0;
  std::optional<Eigen::Isometry3d> map_correction;  // of the current frame (VisualFrameResult::T_new_old)

  VisualFrameResult track(ExtractedImage image, std::vector<PixelDepth> hints);
  std::vector<double> keypointDepths(const std::vector<PixelDepth>& hints) const;
  void initialize(const std::vector<double>& depths, VisualFrameResult& result);
  bool initializeFromDepths(const std::vector<double>& depths, VisualFrameResult& result);
  void setReference(const std::vector<double>& depths);
  void startTracking(const Keyframe& keyframe, const InitialMap& built);
  bool trackFrame(VisualFrameResult& result);
  void recoverOrRestart(const std::vector<PixelDepth>& hints, VisualFrameResult& result);
  bool relocalize(VisualFrameResult& result);
  void loseTracking();
  void newMap();
  bool needKeyframe() const;
  void insertKeyframe();
  std::vector<int> pendingFusionLines();
  void attachLidarPoses();
  void correctWithOdometry(int keyframe);
};

// Every few keyframes the whole map is pulled onto the LiDAR poses
// (module/odometry_map_correction.h), once the odometry is aligned with it.
void VisualSlam::Impl::correctWithOdometry(int keyframe) {
  const MapCorrectionConfig& c = config.modules.map_correction;
  if (!config.modules.use_lidar_pose_priors || c.every_keyframes == 0 || !map.T_world_odom()) return;
  if (++keyframes_since_correction < c.every_keyframes) return;
  keyframes_since_correction = 0;
  const MapCorrectionResult r = correctMapWithOdometry(map, c);
  if (r.graph.solved) map_correction = r.T_new_old.at(keyframe);
}

// Keyframes meet the LiDAR poses of their times, whichever came first (the
// initial pair's first view is older than the poses delivered before it).
void VisualSlam::Impl::attachLidarPoses() {
  if (lidar_poses.empty()) return;
  const double oldest = lidar_poses.front().t;
  const auto& keyframes = map.keyframes();
  for (auto it = keyframes.rbegin(); it != keyframes.rend() && it->second.timestamp >= oldest; ++it) {
    if (it->second.T_odom_camera) continue;
    for (const StampedPose& pose : lidar_poses) {
      if (pose.t != it->second.timestamp) continue;
      map.setOdometryPose(it->first, pose.T_world_frame);
      break;
    }
  }
}

VisualFrameResult VisualSlam::Impl::track(ExtractedImage image, std::vector<PixelDepth> hints) {
  ++frame_index;
  current_has_pose = false;
  current_keyframe = -1;
  map_correction.reset();
  VisualFrameResult result;
  result.timestamp = image.timestamp;
  const ImageStatistics stats = image.stats;
  result.health.brightness = stats.brightness;
  result.health.contrast = stats.contrast;
  current = TrackedFrame{};
  current.features = std::move(image.features);
  result.health.keypoints = static_cast<int>(current.features.points.size());
  result.health.segments = static_cast<int>(current.features.lines.size());
  const bool usable = isUsable(stats, config.usability) && result.health.keypoints >= config.min_keypoints;
  if (!usable) {
    if (state != TrackingState::kInitializing) loseTracking();
    reference.reset();  // an unusable frame breaks the initialisation pair
  } else {
    current.grid = FeatureGrid(current.features.points, current.features.width, current.features.height);
    if (state == TrackingState::kInitializing) {
      initialize(keypointDepths(hints), result);
    } else if (state == TrackingState::kTracking) {
      if (!trackFrame(result)) loseTracking();
    } else {
      recoverOrRestart(hints, result);
    }
  }
  result.state = state;
  result.map_id = map_id;
  result.metric = metric;
  result.pose_valid = current_has_pose;
  if (current_has_pose) result.T_world_camera = current.T_camera_world.inverse();
  result.health.tracked_points = current.point_inliers;
  result.health.tracked_lines = current.line_inliers;
  result.keyframe = current_keyframe >= 0;
  result.fusion.T_new_old = map_correction;
  attachLidarPoses();
  if (current_has_pose && current.information) {
    result.fusion.pose_information = current.information;
    result.fusion.anchor_time = medianFirstSeen(map, current.point_landmark);
    if (!result.keyframe) result.replay.observations = trackedObservations(current);
  }
  result.fusion.T_world_odom = map.T_world_odom();
  if (current_has_pose && map.hasKeyframe(reference_keyframe)) {
    result.replay.reference_keyframe = reference_keyframe;
    result.replay.T_keyframe_camera = map.keyframe(reference_keyframe).T_camera_world * current.T_camera_world.inverse();
  }
  return result;
}

// The depth of the surface under each keypoint of the current frame (NaN:
// none), read from the hints around it.
std::vector<double> VisualSlam::Impl::keypointDepths(const std::vector<PixelDepth>& hints) const {
  return surfaceDepths(hints, rawKeypointPixels(current.features), config.depth_radius_px, current.features.width,
                       current.features.height);
}

void VisualSlam::Impl::setReference(const std::vector<double>& depths) {
  reference_depths = depths;
  const auto hinted = std::count_if(depths.begin(), depths.end(), [](double z) { return std::isfinite(z); });
  // Hints are given but too few reach keypoints (e.g. the LiDAR sweep was
  // elsewhere at this image's time): a later frame is a better metric anchor.
  const bool unhinted = hinted < config.modules.initializer.min_depth_hints;
  if (hints_given && unhinted && skipped_references < config.max_unhinted_references) {
    ++skipped_references;
    reference.reset();
    return;
  }
  skipped_references = 0;
  reference = current;
  reference_time = current.features.timestamp;
  reference_frame = frame_index;
}

// A frame whose keypoints have LiDAR depth starts the map alone; without
// (no LiDAR, or the sweep elsewhere) two views with enough parallax do.
void VisualSlam::Impl::initialize(const std::vector<double>& depths, VisualFrameResult& result) {
  if (initializeFromDepths(depths, result)) return;
  if (!reference || frame_index - reference_frame > config.max_init_frames) return setReference(depths);
  const std::vector<PointMatch> matches = matchInWindow(reference->features, current.features, current.grid,
                                                        config.init_window_px, config.modules.point_matching);
  if (static_cast<int>(matches.size()) < config.min_init_matches) return setReference(depths);
  std::vector<TwoViewMatch> pairs;
  std::vector<DepthHint> hints;
  for (const PointMatch& m : matches) {
    pairs.push_back({m.index1, m.index2});
    if (std::isfinite(reference_depths[m.index1])) hints.push_back({m.index1, reference_depths[m.index1]});
  }
  initializer.setDepthHints(hints);
  const auto init = initializer.initialize(reference->features.points, current.features.points, pairs);
  if (!init) return;
  const auto built = buildInitialMap(map, {reference_time, &reference->features},
                                     {current.features.timestamp, &current.features}, *init, pairs, K, config.modules,
                                     config.modules.initializer.min_triangulated);
  if (!built) return setReference(depths);
  metric = init->metric;
  mapper.addRecentLines(built->lines, built->keyframe2);
  const Keyframe& k2 = map.keyframe(built->keyframe2);
  startTracking(k2, *built);
  current_keyframe = built->keyframe2;
  result.initial_reference = StampedPose{reference_time, map.keyframe(built->keyframe1).T_camera_world.inverse()};
  result.initial_reference_keyframe = built->keyframe1;
  result.health.inlier_ratio = static_cast<double>(init->num_triangulated) / std::max<size_t>(1, pairs.size());
  // Constant velocity per frame: the initial motion spread over its frames.
  const int frames = std::max(1, frame_index - reference_frame);
  motion = {expSE3(logSE3(k2.T_camera_world) / frames), (current.features.timestamp - reference_time) / frames};
}

bool VisualSlam::Impl::initializeFromDepths(const std::vector<double>& depths, VisualFrameResult& result) {
  const int min_points = std::max(config.modules.initializer.min_triangulated,
                                  static_cast<int>(std::ceil(config.min_depth_share * depths.size())));
  const auto built = buildDepthMap(map, {current.features.timestamp, &current.features}, depths, K, min_points);
  if (!built) return false;
  metric = true;
  startTracking(map.keyframe(built->keyframe1), *built);
  current_keyframe = built->keyframe1;
  result.health.inlier_ratio = 1.0;  // every point is seen where it was made
  motion = ConstantVelocity{};
  return true;
}

// The current frame is the map's newest keyframe: tracking goes on from it.
void VisualSlam::Impl::startTracking(const Keyframe& keyframe, const InitialMap& built) {
  const int id = built.keyframe2 >= 0 ? built.keyframe2 : built.keyframe1;
  mapper.addRecentPoints(built.points, id);
  const auto observed = [](const std::vector<int>& ids) {
    return static_cast<int>(std::count_if(ids.begin(), ids.end(), [](int i) { return i >= 0; }));
  };
  current.T_camera_world = keyframe.T_camera_world;
  current.point_landmark = keyframe.point_landmark;
  current.line_landmark = keyframe.line_landmark;
  current.point_inliers = observed(keyframe.point_landmark);
  current.line_inliers = observed(keyframe.line_landmark);
  current_has_pose = true;
  last_time = current.features.timestamp;
  T_last = keyframe.T_camera_world;
  last_points = observedLandmarks(keyframe.point_landmark);
  reference_keyframe = id;
  last_keyframe_frame = frame_index;
  reference.reset();
  state = TrackingState::kTracking;
}

std::vector<int> VisualSlam::Impl::pendingFusionLines() {
  std::vector<int> ids;
  std::vector<FusionLineWait> keep;
  for (const FusionLineWait& w : fusion_lines) {
    if (!map.hasLine(w.line)) continue;
    if (frame_index > w.until_frame) {
      if (map.line(w.line).observations.empty()) map.removeLine(w.line);  // never reached a keyframe
      continue;
    }
    ids.push_back(w.line);
    keep.push_back(w);
  }
  fusion_lines = keep;
  return ids;
}

bool VisualSlam::Impl::trackFrame(VisualFrameResult& result) {
  if (!map.hasKeyframe(reference_keyframe)) return false;
  LocalKeyframes keyframes = selectLocalKeyframes(map, last_points, reference_keyframe, config.modules.local_map);
  const double now = current.features.timestamp;
  const Eigen::Isometry3d T_predicted = predictPose(motion, T_last, now - last_time);
  const double radius = config.modules.local_map.nearby_radius_depths * medianSceneDepth(map, reference_keyframe);
  for (const int kf : nearbyKeyframes(map, T_predicted, radius, keyframes.keyframes, config.modules.local_map))
    keyframes.keyframes.push_back(kf);
  const LocalMap local = collectLocalMap(map, keyframes.keyframes, pendingFusionLines());
  FrameTrackingResult tracked = trackLocalMap(map, local, T_predicted, K, 1.0, tracker, current);
  if (!tracked.success)  // fall back: no motion, wider window
    tracked = trackLocalMap(map, local, T_last, K, config.recovery_radius_scale, tracker, current);
  if (!tracked.success) return false;
  result.health.inlier_ratio = inlierRatio(current.point_inliers, current.line_inliers, tracked.matches);
  last_points = observedLandmarks(current.point_landmark);
  mapper.countTracking(tracked.visible_points, last_points, tracked.visible_lines,
                       observedLandmarks(current.line_landmark));
  motion = {current.T_camera_world * T_last.inverse(), now - last_time};
  last_time = now;
  T_last = current.T_camera_world;
  current_has_pose = true;
  lost_frames = 0;
  if (needKeyframe()) insertKeyframe();
  return true;
}

bool VisualSlam::Impl::needKeyframe() const {
  // View overlap (ORB-SLAM's c2, measured against what the reference keyframe
  // tracked when it was inserted: its landmark count includes the points the
  // mapper triangulated afterwards, which a frame only partly re-finds, so a
  // ratio against it fired at every minimum interval).
  int ref_tracked = reference_tracked_points;
  if (reference_tracked_keyframe != reference_keyframe) {
    ref_tracked = 0;
    for (const int id : map.keyframe(reference_keyframe).point_landmark) ref_tracked += id >= 0;
  }
  return keyframeNeeded(config.modules.keyframes, current.point_inliers, ref_tracked, frame_index - last_keyframe_frame);
}

void VisualSlam::Impl::insertKeyframe() {
  reference_tracked_points = current.point_inliers;  // before the mapper adds points
  Keyframe k;
  k.timestamp = current.features.timestamp;
  k.T_camera_world = current.T_camera_world;
  k.features = current.features;
  const int id = map.addKeyframe(std::move(k));
  for (size_t i = 0; i < current.point_landmark.size(); ++i)
    if (current.point_landmark[i] >= 0) map.addPointObservation(current.point_landmark[i], id, static_cast<int>(i));
  for (size_t i = 0; i < current.line_landmark.size(); ++i)
    if (current.line_landmark[i] >= 0) map.addLineObservation(current.line_landmark[i], id, static_cast<int>(i));
  mapper.process(map, id);
  correctWithOdometry(id);
  // BA (and the odometry correction) moved the keyframe: the tracked pose follows it.
  current.T_camera_world = map.keyframe(id).T_camera_world;
  T_last = current.T_camera_world;
  reference_keyframe = id;
  reference_tracked_keyframe = id;
  current_keyframe = id;
  last_keyframe_frame = frame_index;
}

void VisualSlam::Impl::loseTracking() {
  if (state == TrackingState::kTracking) lost_frames = 0;
  state = TrackingState::kLost;
  ++lost_frames;
}

void VisualSlam::Impl::newMap() {
  retired_maps.push_back(std::move(map));
  map = VisualMap();
  mapper.reset();
  fusion_lines.clear();
  ++map_id;
  metric = false;
  keyframes_since_correction = 0;
  reference.reset();
  reference_keyframe = -1;
  reference_tracked_keyframe = -1;  // keyframe ids restart with the new map
  state = TrackingState::kInitializing;
}

// Relocalisation into the old map (tracking/relocalization.h).
bool VisualSlam::Impl::relocalize(VisualFrameResult& result) {
  const std::vector<Eigen::Isometry3d> guesses =
      relocalizationGuesses(map, predictPose(motion, T_last, current.features.timestamp - last_time), T_last,
                            reference_keyframe, config.relocalize_candidates);
  const LocalKeyframes keyframes = selectLocalKeyframes(map, last_points, reference_keyframe, config.modules.local_map);
  const LocalMap local = collectLocalMap(map, keyframes.keyframes, {});
  const std::optional<FrameTrackingResult> tracked = relocalizeFrame(
      map, local, guesses, K, config.recovery_radius_scale, config.relocalize_min_inliers, tracker, current);
  if (!tracked) return false;
  state = TrackingState::kTracking;
  motion = ConstantVelocity{};
  last_time = current.features.timestamp;
  T_last = current.T_camera_world;
  current_has_pose = true;
  lost_frames = 0;
  last_points = observedLandmarks(current.point_landmark);
  result.health.inlier_ratio = inlierRatio(current.point_inliers, current.line_inliers, tracked->matches);
  return true;
}

void VisualSlam::Impl::recoverOrRestart(const std::vector<PixelDepth>& hints, VisualFrameResult& result) {
  if (lost_frames <= config.relocalize_frames && map.hasKeyframe(reference_keyframe)) {
    if (!relocalize(result)) ++lost_frames;
    return;
  }
  newMap();
  initialize(keypointDepths(hints), result);
}

VisualSlam::VisualSlam(const VisualSlamConfig& config, const PinholeCamera& camera)
    : impl_(std::make_unique<Impl>(config, camera)) {
  quietSolverLogging();
}
VisualSlam::~VisualSlam() = default;

VisualFrameResult VisualSlam::track(const ImageFrame& frame) {
  return track(extractImage(impl_->extractor, frame));
}

VisualFrameResult VisualSlam::track(ExtractedImage image) {
  const PinholeCamera& cam = impl_->camera;
  if (image.features.width != cam.width() || image.features.height != cam.height()) {
    throw Error("VisualSlam::track", "features of a " + std::to_string(image.features.width) + "x" +
                                         std::to_string(image.features.height) + " image, camera is " +
                                         std::to_string(cam.width()) + "x" + std::to_string(cam.height()));
  }
  std::vector<PixelDepth> hints;
  hints.swap(impl_->next_hints);
  impl_->hints_given = impl_->next_hints_given;
  impl_->next_hints_given = false;
  return impl_->track(std::move(image), std::move(hints));
}

void VisualSlam::setDepthHints(std::vector<PixelDepth> hints) {
  impl_->next_hints = std::move(hints);
  impl_->next_hints_given = true;
}
bool VisualSlam::needsDepthHints() const { return impl_->state != TrackingState::kTracking; }
TrackingState VisualSlam::state() const { return impl_->state; }
int VisualSlam::mapId() const { return impl_->map_id; }
const VisualMap& VisualSlam::map() const { return impl_->map; }
const std::vector<VisualMap>& VisualSlam::retiredMaps() const { return impl_->retired_maps; }

std::optional<Eigen::Isometry3d> VisualSlam::relocateInFinalMap(const VisualFrameResult& result,
                                                                const Eigen::Isometry3d& T_world_camera_initial) const {
  if (result.replay.observations.points.empty() && result.replay.observations.lines.empty()) return std::nullopt;
  if (result.map_id < 0 || result.map_id > impl_->map_id) return std::nullopt;
  const VisualMap& map = result.map_id == impl_->map_id ? impl_->map : impl_->retired_maps[result.map_id];
  const auto T_camera_world =
      relocateInMap(map, result.replay.observations, T_world_camera_initial.inverse(), impl_->K, impl_->tracker);
  if (!T_camera_world) return std::nullopt;
  return T_camera_world->inverse();
}

std::vector<ImageLineSegment> VisualSlam::lineSegments() const {
  return rawLineSegments(impl_->current.features, impl_->camera);
}

int VisualSlam::addFusionLine(int segment, const Eigen::Vector3d& A_camera, const Eigen::Vector3d& B_camera,
                              const Eigen::Vector3d& direction_camera) {
  Impl& s = *impl_;
  if (!A_camera.allFinite() || !B_camera.allFinite() || !direction_camera.allFinite() ||
      !(direction_camera.norm() > 0.0) || !((B_camera - A_camera).norm() > 1e-9)) {
    throw Error("VisualSlam::addFusionLine", "endpoints and direction must be finite, distinct and non-zero");
  }
  if (segment < 0 || static_cast<size_t>(segment) >= s.current.features.lines.size())
    throw Error("VisualSlam::addFusionLine", "segment index " + std::to_string(segment) + " out of range");
  if (!s.current_has_pose) return -1;
  const Eigen::Isometry3d T_world_camera = s.current.T_camera_world.inverse();
  const Eigen::Vector3d d_fu = T_world_camera.linear() * direction_camera;
  // The segment may already observe a landmark, through the frame or, when
  // the frame became a keyframe, one the mapper triangulated since.
  int existing = s.current.line_landmark[segment];
  if (existing < 0 && s.current_keyframe >= 0 && s.map.hasKeyframe(s.current_keyframe))
    existing = s.map.keyframe(s.current_keyframe).line_landmark[segment];
  if (s.map.hasLine(existing)) {
    s.map.setFusionDirection(existing, d_fu);
    return existing;
  }
  // Paper eq.: m = A x B, d = B - A, moved to the world by the current pose.
  const PluckerLine line_world = PluckerLine::fromPoints(A_camera, B_camera).transformed(T_world_camera);
  const int id = s.map.addLineLandmark(line_world, T_world_camera * A_camera, T_world_camera * B_camera,
                                       s.current.features.line_descriptors.empty()
                                           ? cv::Mat()
                                           : s.current.features.line_descriptors.row(segment));
  s.map.line(id).from_fusion = true;
  s.map.setFusionDirection(id, d_fu);
  s.current.line_landmark[segment] = id;
  if (s.current_keyframe >= 0) {
    s.map.addLineObservation(id, s.current_keyframe, segment);
    s.mapper.addRecentLines({id}, s.current_keyframe);
  }
  s.fusion_lines.push_back({id, s.frame_index + s.config.fusion_line_lifetime});
  return id;
}

void VisualSlam::addLidarPose(double t, const Eigen::Isometry3d& T_odom_camera) {
  if (!isRigidTransform(T_odom_camera))
    throw Error("VisualSlam::addLidarPose", "the pose at t=" + std::to_string(t) + " is not a rigid transform");
  Impl& s = *impl_;
  if (!s.config.modules.use_lidar_pose_priors) return;
  s.lidar_poses.push_back({t, T_odom_camera});
  if (s.lidar_poses.size() > s.config.lidar_pose_buffer) s.lidar_poses.pop_front();
  s.attachLidarPoses();
}

std::vector<Eigen::Vector2d> VisualSlam::keypointPixels() const { return rawKeypointPixels(impl_->current.features); }

bool VisualSlam::currentIsKeyframe() const {
  return impl_->current_keyframe >= 0 && impl_->map.hasKeyframe(impl_->current_keyframe);
}

void VisualSlam::setKeypointDepths(const std::vector<double>& depths) {
  const size_t keypoints = impl_->current.features.keypoints.size();
  if (depths.size() != keypoints) {
    throw Error("VisualSlam::setKeypointDepths", std::to_string(depths.size()) + " depths for " +
                                                     std::to_string(keypoints) + " keypoints of the current frame");
  }
  Impl& s = *impl_;
  if (!currentIsKeyframe() || !s.config.modules.use_keypoint_depths) return;
  s.map.setKeypointDepths(s.current_keyframe, depths);
  // The mapper has triangulated this keyframe already: the keypoints still
  // without a landmark get one from their depth.
  const std::vector<int> created = createDepthPoints(s.map, s.current_keyframe, s.K, s.config.triangulation);
  s.mapper.addRecentPoints(created, s.current_keyframe);
}

}  // namespace lvslam::visual
