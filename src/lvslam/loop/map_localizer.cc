#include "lvslam/loop/map_localizer.h"

#include <cstdlib>

#include <fmt/format.h>

#include "lvslam/loop/loop_candidates.h"
#include "lvslam/loop/loop_closure.h"

namespace lvslam::loop {

namespace {

std::vector<Eigen::Vector3f> positionsOf(const std::vector<lidar::FeaturePoint>& points) {
  std::vector<Eigen::Vector3f> p;
  p.reserve(points.size());
  for (const lidar::FeaturePoint& point : points) p.push_back(point.p);
  return p;
}

}  // namespace

MapLocalizer::MapLocalizer(std::vector<LoopKeyframe> map, const LoopClosureConfig& config,
                           const lidar::RegistrationConfig& registration)
    : map_(std::move(map)), config_(config), registration_(registration) {
  descriptors_.reserve(map_.size() + 1);
  for (const LoopKeyframe& kf : map_) descriptors_.push_back(makeScanContext(positionsOf(kf.points), config_.scan_context));
}

LoopVerification MapLocalizer::verifyAt(const LoopKeyframe& keyframe, const LoopCandidate& candidate) const {
  return verifyLoop(keyframe.points,
                    submapAround(map_, candidate.index, config_.submap_keyframes, static_cast<int>(map_.size()) - 1),
                    candidate.match.yaw, config_, registration_);
}

void MapLocalizer::addKeyframe(const LoopKeyframe& keyframe) {
  const int query = static_cast<int>(query_paths_.size());
  query_paths_.push_back(keyframe.path_length);
  if (map_.empty()) return;
  // The map's keyframes and the query, every map keyframe a candidate.
  descriptors_.push_back(makeScanContext(positionsOf(keyframe.points), config_.scan_context));
  std::vector<double> paths(descriptors_.size(), 0.0);
  paths.back() = 1.0;
  const std::vector<LoopCandidate> candidates =
      findLoopCandidates(descriptors_, paths, 0.0, config_.ring_key_candidates);
  descriptors_.pop_back();
  if (candidates.empty()) return;
  const LoopCandidate& best = candidates.front();
  MapMatchRecord record;
  record.query = query;
  record.map_keyframe = best.index;
  record.query_t = keyframe.t;
  record.descriptor_distance = best.match.distance;
  if (best.match.distance > config_.max_descriptor_distance) {
    record.reason = fmt::format("descriptor distance {:.3f} (> {:.3f})", best.match.distance,
                                config_.max_descriptor_distance);
    result_.matches.push_back(std::move(record));
    return;
  }
  record.verified = true;
  record.verification = verifyAt(keyframe, best);
  if (!record.verification.reason.empty()) {
    record.reason = record.verification.reason;
    result_.matches.push_back(std::move(record));
    return;
  }
  const Eigen::Isometry3d T_map_query =
      map_[static_cast<std::size_t>(best.index)].T_odom_lidar * record.verification.T_candidate_query;
  record.T_map_odom = T_map_query * keyframe.T_odom_lidar.inverse();
  // A place the map holds twice (the twin rooms) verifies at both: the next
  // best candidate outside the first one's submap is verified too, and a
  // second pose in the map for the same scan makes the match ambiguous.
  for (const LoopCandidate& other : candidates) {
    if (std::abs(other.index - best.index) <= config_.submap_keyframes) continue;
    if (other.match.distance > config_.max_descriptor_distance) break;
    const LoopVerification alternative = verifyAt(keyframe, other);
    if (alternative.reason.empty()) {
      const Eigen::Isometry3d T_map_alternative =
          map_[static_cast<std::size_t>(other.index)].T_odom_lidar * alternative.T_candidate_query;
      const std::string off = offByDrift(T_map_query.inverse() * T_map_alternative, 0.0, config_);
      if (!off.empty()) record.reason = fmt::format("ambiguous: map keyframe {} fits as well, {}", other.index, off);
    }
    break;
  }
  if (!record.reason.empty()) {
    result_.matches.push_back(std::move(record));
    return;
  }
  // What this match says of the query's pose in the map, beyond what an
  // earlier match and the odometry between the two say.
  const auto offFrom = [&](const MapMatchRecord& earlier) {
    const Eigen::Isometry3d offset = (earlier.T_map_odom * keyframe.T_odom_lidar).inverse() * T_map_query;
    return offByDrift(offset, keyframe.path_length - query_paths_[static_cast<std::size_t>(earlier.query)], config_);
  };
  if (result_.T_map_odom) {
    const std::string off = offFrom(result_.matches[verified_.front()]);
    if (off.empty()) ++result_.agreeing;
    record.reason = off.empty() ? "" : "disagrees with the localisation: " + off;
  } else {
    for (std::size_t i = 0; i < verified_.size() && !result_.T_map_odom; ++i) {
      MapMatchRecord& earlier = result_.matches[verified_[i]];
      if (!offFrom(earlier).empty()) continue;
      // The earlier one becomes the first verified match: the later ones are judged against it.
      earlier.reason.clear();
      verified_ = {verified_[i]};
      result_.T_map_odom = earlier.T_map_odom;
      result_.localized_t = keyframe.t;
      result_.agreeing = 2;
    }
    if (!result_.T_map_odom) {
      record.reason = "not yet confirmed by a second match";
      verified_.push_back(result_.matches.size());
    }
  }
  result_.matches.push_back(std::move(record));
}

}  // namespace lvslam::loop
