#include "lvslam/system/offline/loop_report.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "lvslam/core/se3.h"
#include "lvslam/eval/json_writer.h"

namespace lvslam::system {

namespace {

using eval::JsonObject;

std::string candidateJson(const loop::LoopCandidateRecord& c) {
  JsonObject o;
  o.addCount("query", static_cast<std::size_t>(c.query))
      .addCount("candidate", static_cast<std::size_t>(c.candidate))
      .addNumber("query_t", c.query_t)
      .addNumber("candidate_t", c.candidate_t)
      .addNumber("ring_key_distance", c.ring_key_distance)
      .addNumber("descriptor_distance", c.descriptor_distance)
      .addNumber("descriptor_yaw_deg", c.yaw * 180.0 / M_PI)
      .addRaw("accepted", c.reason.empty() ? "true" : "false")
      .addString("reason", c.reason);
  if (c.verified) {
    const loop::LoopVerification& v = c.verification;
    const Eigen::Vector3d t = v.T_candidate_query.translation();
    o.addNumber("rms_m", v.rms)
        .addNumber("inlier_ratio", v.inlier_ratio)
        .addCount("correspondences", v.correspondences)
        .addRaw("degenerate", v.degenerate ? "true" : "false")
        .addNumber("localizability", v.localizability)
        .addRaw("T_candidate_query_xyz", eval::jsonArray({t.x(), t.y(), t.z()}))
        .addNumber("T_candidate_query_deg", rotationAngle(v.T_candidate_query) * 180.0 / M_PI);
  }
  if (c.reason.empty()) o.addNumber("graph_weight", c.graph_weight);
  return o.str();
}

double largestKeyframeMove(const loop::LoopClosureResult& result) {
  double largest = 0.0;
  for (std::size_t k = 0; k < result.T_odom_lidar.size() && k < result.T_odom_lidar_corrected.size(); ++k)
    largest = std::max(largest,
                       (result.T_odom_lidar_corrected[k].translation() - result.T_odom_lidar[k].translation()).norm());
  return largest;
}

std::size_t verifiedCount(const loop::LoopClosureResult& result) {
  return static_cast<std::size_t>(std::count_if(result.candidates.begin(), result.candidates.end(),
                                                [](const loop::LoopCandidateRecord& c) { return c.verified; }));
}

std::string mapMatchJson(const loop::MapMatchRecord& m) {
  JsonObject o;
  o.addCount("query", static_cast<std::size_t>(m.query))
      .addCount("map_keyframe", static_cast<std::size_t>(m.map_keyframe))
      .addNumber("query_t", m.query_t)
      .addNumber("descriptor_distance", m.descriptor_distance)
      .addRaw("verified", m.verified ? "true" : "false")
      .addRaw("taken", m.verified && m.reason.empty() ? "true" : "false")
      .addString("reason", m.reason);
  if (m.verified) o.addNumber("rms_m", m.verification.rms).addNumber("inlier_ratio", m.verification.inlier_ratio);
  return o.str();
}

std::string mapLocalizationJson(const loop::MapLocalization& l) {
  std::vector<std::string> matches;
  for (const loop::MapMatchRecord& m : l.matches) matches.push_back(mapMatchJson(m));
  JsonObject o;
  o.addRaw("localized", l.T_map_odom ? "true" : "false").addCount("tries", l.matches.size());
  if (l.T_map_odom) {
    const Eigen::Vector3d t = l.T_map_odom->translation();
    const Eigen::Quaterniond q(l.T_map_odom->linear());
    o.addNumber("localized_t", l.localized_t)
        .addCount("agreeing", static_cast<std::size_t>(l.agreeing))
        .addRaw("T_map_odom_xyz", eval::jsonArray({t.x(), t.y(), t.z()}))
        .addRaw("T_map_odom_qxyzw", eval::jsonArray({q.x(), q.y(), q.z(), q.w()}));
  }
  return o.addRaw("match_log", fmt::format("[{}]", fmt::join(matches, ","))).str();
}

}  // namespace

std::string loopJson(const loop::LoopClosureResult& result) {
  std::vector<std::string> candidates;
  for (const loop::LoopCandidateRecord& c : result.candidates) candidates.push_back(candidateJson(c));
  JsonObject o;
  if (result.map_localization) o.addRaw("map_localization", mapLocalizationJson(*result.map_localization));
  return o.addString("odometry", result.odometry)
      .addCount("keyframes", result.keyframe_times.size())
      .addRaw("keyframe_t", eval::jsonArray(result.keyframe_times))
      .addCount("candidates", result.candidates.size())
      .addCount("verified", verifiedCount(result))
      .addCount("accepted", result.accepted())
      .addRaw("graph_solved", result.solved ? "true" : "false")
      .addNumber("largest_keyframe_move_m", largestKeyframeMove(result))
      .addRaw("candidate_log", fmt::format("[{}]", fmt::join(candidates, ",")))
      .str();
}

std::string formatLoopSummary(const loop::LoopClosureResult& applied, const loop::LoopClosureResult& live) {
  const std::string gated =
      applied.odometry == live.odometry
          ? ""
          : fmt::format(" (gated on the {} trajectory; {} on the {} odometry)", applied.odometry, live.accepted(),
                        live.odometry);
  return fmt::format("loop closure: {} keyframes, {} candidates, {} verified, {} accepted{}; keyframes moved up to "
                     "{:.3f} m{}\n",
                     applied.keyframe_times.size(), applied.candidates.size(), verifiedCount(applied),
                     applied.accepted(), gated, largestKeyframeMove(applied),
                     applied.solved ? "" : " (the graph failed to solve: not applied)") +
         (live.map_localization ? formatMapLocalization(*live.map_localization) : "");
}

std::string formatMapLocalization(const loop::MapLocalization& l) {
  const auto taken = [](const loop::MapMatchRecord& m) { return m.verified && m.reason.empty(); };
  const auto verified = [](const loop::MapMatchRecord& m) { return m.verified && m.verification.reason.empty(); };
  const auto count = [&l](auto predicate) {
    return static_cast<std::size_t>(std::count_if(l.matches.begin(), l.matches.end(), predicate));
  };
  if (!l.T_map_odom)
    return fmt::format("map: not localised in the saved map ({} keyframes tried, {} verified by the ICP, no two "
                       "agreeing)\n",
                       l.matches.size(), count(verified));
  const Eigen::Vector3d t = l.T_map_odom->translation();
  return fmt::format("map: localised at t={:.3f} ({} keyframes tried, {} verified by the ICP, {} agreeing); the "
                     "run's world in the map: ({:.3f}, {:.3f}, {:.3f}) m, {:.2f} deg\n",
                     l.localized_t, l.matches.size(), count(verified), count(taken), t.x(), t.y(), t.z(),
                     rotationAngle(*l.T_map_odom) * 180.0 / M_PI);
}

}  // namespace lvslam::system
