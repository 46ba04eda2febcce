#pragma once
// Localisation in a saved map (lvslam run --map-in): each keyframe of the
// run looks for its place among the map's keyframes by Scan Context, over
// the whole map, and a candidate is verified by the multi-metric ICP
// against the map keyframe and its neighbours, as a loop is. A verified
// match gives the run's odometry frame in the map's frame. One match can
// be a look-alike place (the twin rooms pass the ICP as each other), so the
// run counts as localised only once a match from a later keyframe agrees
// with an earlier one within the odometry's drift over the path between
// them (offByDrift), as ORB-SLAM asks consecutive loop candidates to agree,
// and a scan that also fits a second place in the map is not used at all
// (a map holding both twin rooms; candidates that verify at the same pose,
// the same place mapped twice, do not count). A place the world holds twice and the
// map once cannot be told apart by any of this: matches in the twin the map
// lacks agree with each other and are taken for the one it has.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "lvslam/lidar/lidar_config.h"
#include "lvslam/loop/loop_candidates.h"
#include "lvslam/loop/loop_config.h"
#include "lvslam/loop/loop_keyframe.h"
#include "lvslam/loop/loop_verification.h"
#include "lvslam/loop/scan_context.h"

namespace lvslam::loop {

// One keyframe of the run tried against the map.
struct MapMatchRecord {
  int query = 0;         // the run's keyframe index
  int map_keyframe = 0;  // the best candidate in the map
  double query_t = 0.0;
  double descriptor_distance = 0.0;
  bool verified = false;  // reached the ICP
  LoopVerification verification;
  // The run's odometry frame in the map's, from this match (verified ones).
  Eigen::Isometry3d T_map_odom = Eigen::Isometry3d::Identity();
  std::string reason;  // why it was not taken, empty when verified and agreeing
};

struct MapLocalization {
  std::vector<MapMatchRecord> matches;
  // Once two verified matches agree: the earlier one's T_map_odom, and the
  // time of the keyframe that confirmed it (from then on, online, the run
  // knows where it is in the map).
  std::optional<Eigen::Isometry3d> T_map_odom;
  double localized_t = 0.0;
  int agreeing = 0;  // verified matches within the drift of the first, itself included
};

class MapLocalizer {
 public:
  // `map`: the saved map's keyframes, their T_odom_lidar in the map's frame.
  MapLocalizer(std::shared_ptr<const std::vector<LoopKeyframe>> map, const LoopClosureConfig& config,
               const lidar::RegistrationConfig& registration);

  // Tries the run's next keyframe (T_odom_lidar in the run's odometry frame).
  void addKeyframe(const LoopKeyframe& keyframe);
  const MapLocalization& result() const { return result_; }
  std::size_t mapKeyframes() const { return map_->size(); }

 private:
  LoopVerification verifyAt(const LoopKeyframe& keyframe, const LoopCandidate& candidate) const;

  // Whether the scan also verifies at a place of the map other than
  // `T_map_query` (at `best`): the reason if so, else empty.
  std::string ambiguity(const LoopKeyframe& keyframe, const std::vector<LoopCandidate>& candidates,
                        const LoopCandidate& best, const Eigen::Isometry3d& T_map_query) const;
  std::string offFrom(const MapMatchRecord& earlier, std::size_t index) const;
  // The verified match `index` judged against the localisation's first match.
  void judge(std::size_t index);

  std::shared_ptr<const std::vector<LoopKeyframe>> map_;
  std::vector<ScanContext> descriptors_;
  LoopClosureConfig config_;
  lidar::RegistrationConfig registration_;
  std::vector<double> query_paths_;  // of the run's keyframes tried, by index
  std::vector<Eigen::Isometry3d> query_poses_;
  std::vector<std::size_t> verified_;  // indices into result_.matches, before the localisation
  std::size_t first_ = 0;              // the match that placed the run
  MapLocalization result_;
};

}  // namespace lvslam::loop
