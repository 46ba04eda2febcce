#pragma once
// The visual subsystem's map: keyframes, point and line landmarks, the
// observations between them and the covisibility graph they induce. Ids are
// assigned here and never reused; iteration order is by id (deterministic).
#include <map>
#include <optional>
#include <vector>

#include "lvslam/visual/data/covisibility_graph.h"
#include "lvslam/visual/data/keyframe.h"
#include "lvslam/visual/data/landmarks.h"

namespace lvslam::visual {

class VisualMap {
 public:
  VisualMap() = default;
  // Copies rebuild the id index; moves keep it (map nodes do not move).
  VisualMap(const VisualMap& other);
  VisualMap& operator=(const VisualMap& other);
  VisualMap(VisualMap&&) noexcept = default;
  VisualMap& operator=(VisualMap&&) noexcept = default;

  // Takes the keyframe, assigns its id and sizes its landmark tables to its features.
  int addKeyframe(Keyframe keyframe);
  int addPointLandmark(const Eigen::Vector3d& p_world, const cv::Mat& descriptor);
  int addLineLandmark(const PluckerLine& line_world, const Eigen::Vector3d& start_world,
                      const Eigen::Vector3d& end_world, const cv::Mat& descriptor);

  // Feature `index` of `keyframe` observes the landmark. Throws lvslam::Error
  // on unknown ids, an index out of range or a feature that already observes
  // a landmark.
  void addPointObservation(int point, int keyframe, int index);
  void addLineObservation(int line, int keyframe, int index);
  void removePointObservation(int point, int keyframe);
  void removeLineObservation(int line, int keyframe);
  // Duplicate landmarks (ORB-SLAM's MapPoint::Replace): every keyframe
  // observing `from` observes `into` instead (unless it already does), and
  // `from` is removed. Throws lvslam::Error on unknown ids.
  void replacePoint(int from, int into);
  // Drops the landmark with all its observations; its id is not reused.
  void removePoint(int point);
  void removeLine(int line);
  // Drops the keyframe's observations, its covisibility edges and the keyframe
  // (keyframe culling). Landmarks keep their other observations. Its pose
  // stays known relative to a parent (its most covisible keyframe, else the
  // nearest older one): keyframePose() follows the parent as it moves on.
  void removeKeyframe(int keyframe);
  // T_camera_world of a keyframe of this map, removed ones through their
  // parents (ORB-SLAM's spanning tree); none for an id never added.
  std::optional<Eigen::Isometry3d> keyframePose(int keyframe) const;

  void setFusionDirection(int line, const Eigen::Vector3d& d_fu);
  // LiDAR depth per keypoint of the keyframe (index = keypoint index);
  // non-finite or non-positive entries are stored as NaN (no depth). Throws
  // lvslam::Error on an unknown keyframe or a size other than its keypoints'.
  void setKeypointDepths(int keyframe, std::vector<double> depths);

  // The LiDAR odometry's camera pose T_odom_camera at the keyframe's time.
  // The first one given fixes the map's alignment T_world_odom (the
  // keyframe's pose at that moment); from then on odometryPrior() moves each
  // such pose into the map. Throws lvslam::Error on an unknown keyframe or a
  // pose that is not a finite rigid transform.
  void setOdometryPose(int keyframe, const Eigen::Isometry3d& T_odom_camera);
  const std::optional<Eigen::Isometry3d>& T_world_odom() const { return T_world_odom_; }
  // T_camera_world the odometry gives for the keyframe; none without a pose.
  std::optional<Eigen::Isometry3d> odometryPrior(int keyframe) const;

  Keyframe& keyframe(int id);
  const Keyframe& keyframe(int id) const;
  PointLandmark& point(int id);
  const PointLandmark& point(int id) const;
  LineLandmark& line(int id);
  const LineLandmark& line(int id) const;
  bool hasKeyframe(int id) const { return keyframes_.count(id) != 0; }
  // The landmark exists: false for -1, unknown and removed ids.
  bool hasPoint(int id) const;
  bool hasLine(int id) const;

  const std::map<int, Keyframe>& keyframes() const { return keyframes_; }
  const std::map<int, PointLandmark>& points() const { return points_; }
  const std::map<int, LineLandmark>& lines() const { return lines_; }
  const CovisibilityGraph& covisibility() const { return covisibility_; }

  // The keyframe and its n - 1 most covisible neighbours (ORB-SLAM's local window).
  std::vector<int> localWindow(int keyframe, size_t n) const;

 private:
  template <typename Landmark>
  void addObservation(Landmark& landmark, std::vector<int> Keyframe::*table, int keyframe, int index);
  // The point's descriptor: the most central of its observations'.
  void updateDescriptor(PointLandmark& point) const;
  template <typename Landmark>
  void removeObservation(Landmark& landmark, std::vector<int> Keyframe::*table, int keyframe);

  std::map<int, Keyframe> keyframes_;
  std::map<int, PointLandmark> points_;
  std::map<int, LineLandmark> lines_;
  CovisibilityGraph covisibility_;
  // Removed keyframe -> its parent and its pose in the parent's camera frame.
  struct RemovedKeyframe {
    int parent = -1;
    Eigen::Isometry3d T_parent_keyframe = Eigen::Isometry3d::Identity();
  };
  std::map<int, RemovedKeyframe> removed_;
  // The keyframe a removed one is placed against (removeKeyframe); -1 if none.
  int parentFor(int keyframe) const;
  int next_keyframe_id_ = 0;
  std::optional<Eigen::Isometry3d> T_world_odom_;
  // Landmarks by id, for O(1) lookups: every id ever assigned has a slot,
  // null once removed, so the next id is the index's size. Keep the copy
  // constructor's member list in step.
  std::vector<PointLandmark*> point_by_id_;
  std::vector<LineLandmark*> line_by_id_;
};

// Median depth of the keyframe's point landmarks; 0 when it has none.
double medianSceneDepth(const VisualMap& map, int keyframe);

// Time of the keyframe that first observed a landmark (the first of its
// observations); none without any.
std::optional<double> firstSeen(const VisualMap& map, const std::vector<Observation>& observations);

// Median time of the keyframes that first observed the given point
// landmarks (ids < 0 and removed ones skipped): when the part of the map a pose
// rests on was mapped. None without any.
std::optional<double> medianFirstSeen(const VisualMap& map, const std::vector<int>& points);

}  // namespace lvslam::visual
