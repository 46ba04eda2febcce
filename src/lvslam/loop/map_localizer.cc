#include "lvslam/loop/map_localizer.h"

#include <cstdlib>

#include <fmt/format.h>

#include "lvslam/loop/loop_candidates.h"
#include "lvslam/loop/loop_closure.h"

namespace lvslam::loop {

MapLocalizer::MapLocalizer(std::shared_ptr<const std::vector<LoopKeyframe>> map, const LoopClosureConfig& config,
                           const lidar::RegistrationConfig& registration)
    : map_(std::move(map)), config_(config), registration_(registration) {
  descriptors_.reserve(map_->size() + 1);
  for (const LoopKeyframe& kf : *map_)
    descriptors_.push_back(scanContextOf(kf.points, config_.scan_context));
}

LoopVerification MapLocalizer::verifyAt(const LoopKeyframe& keyframe, const LoopCandidate& candidate) const {
  return verifyLoop(keyframe.points,
                    submapAround(*map_, candidate.index, config_.submap_keyframes, static_cast<int>(map_->size()) - 1),
                    candidate.match.yaw, config_, registration_);
}

// A map of several passes holds a place more than once at the same pose;
// a twin room holds it at another. The next candidates outside the best
// one's submap are verified in turn (a few at most): one at the same pose
// is the same place, one elsewhere makes the scan ambiguous.
std::string MapLocalizer::ambiguity(const LoopKeyframe& keyframe, const std::vector<LoopCandidate>& candidates,
                                    const LoopCandidate& best, const Eigen::Isometry3d& T_map_query) const {
  constexpr int kMaxAlternatives = 3;
  int tried = 0;
  for (const LoopCandidate& other : candidates) {
    if (other.match.distance > config_.max_descriptor_distance || tried == kMaxAlternatives) break;
    if (std::abs(other.index - best.index) <= config_.submap_keyframes) continue;
    ++tried;
    const LoopVerification alternative = verifyAt(keyframe, other);
    if (!alternative.reason.empty()) continue;
    const Eigen::Isometry3d T_map_alternative =
        (*map_)[static_cast<std::size_t>(other.index)].T_odom_lidar * alternative.T_candidate_query;
    const std::string off = offByDrift(T_map_query.inverse() * T_map_alternative, 0.0, config_);
    if (!off.empty()) return fmt::format("ambiguous: map keyframe {} fits as well, {}", other.index, off);
  }
  return "";
}

void MapLocalizer::addKeyframe(const LoopKeyframe& keyframe) {
  const int query = static_cast<int>(query_paths_.size());
  query_paths_.push_back(keyframe.path_length);
  query_poses_.push_back(keyframe.T_odom_lidar);
  if (map_->empty()) return;
  // The map's keyframes and the query, every map keyframe a candidate.
  descriptors_.push_back(scanContextOf(keyframe.points, config_.scan_context));
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
      (*map_)[static_cast<std::size_t>(best.index)].T_odom_lidar * record.verification.T_candidate_query;
  record.T_map_odom = T_map_query * keyframe.T_odom_lidar.inverse();
  record.reason = ambiguity(keyframe, candidates, best, T_map_query);
  const std::size_t index = result_.matches.size();
  result_.matches.push_back(std::move(record));
  if (!result_.matches[index].reason.empty()) return;
  if (result_.T_map_odom) {
    judge(index);
    return;
  }
  // Not localised yet: the first earlier verified match this one agrees with
  // confirms both; the earlier one places the run, and every other verified
  // match is judged against it.
  for (const std::size_t earlier : verified_) {
    if (!offFrom(result_.matches[earlier], index).empty()) continue;
    result_.T_map_odom = result_.matches[earlier].T_map_odom;
    result_.localized_t = keyframe.t;
    first_ = earlier;
    for (const std::size_t other : verified_) judge(other);
    judge(index);
    return;
  }
  result_.matches[index].reason = "not yet confirmed by a second match";
  verified_.push_back(index);
}

// What match `index` says of its query's pose in the map beyond what match
// `earlier` and the odometry between their two keyframes say; empty when
// within the drift.
std::string MapLocalizer::offFrom(const MapMatchRecord& earlier, std::size_t index) const {
  const MapMatchRecord& later = result_.matches[index];
  const auto q = static_cast<std::size_t>(later.query);
  const Eigen::Isometry3d T_map_query = later.T_map_odom * query_poses_[q];
  const Eigen::Isometry3d offset = (earlier.T_map_odom * query_poses_[q]).inverse() * T_map_query;
  return offByDrift(offset, std::abs(query_paths_[q] - query_paths_[static_cast<std::size_t>(earlier.query)]),
                    config_);
}

void MapLocalizer::judge(std::size_t index) {
  const std::string off = index == first_ ? "" : offFrom(result_.matches[first_], index);
  result_.matches[index].reason = off.empty() ? "" : "disagrees with the localisation: " + off;
  if (off.empty()) ++result_.agreeing;
}

}  // namespace lvslam::loop
