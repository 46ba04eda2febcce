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

}  // namespace

std::string loopJson(const loop::LoopClosureResult& result) {
  std::vector<std::string> candidates;
  for (const loop::LoopCandidateRecord& c : result.candidates) candidates.push_back(candidateJson(c));
  return JsonObject()
      .addString("odometry", result.odometry)
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
                     applied.solved ? "" : " (the graph failed to solve: not applied)");
}

}  // namespace lvslam::system
