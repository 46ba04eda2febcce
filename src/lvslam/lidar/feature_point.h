#pragma once
// Geometric feature points of one scan, classified as in MULLS (Pan et al.,
// ICRA 2021): what the registration matches and what the fusion framework sees.
#include <cstdint>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace lvslam::lidar {

enum class FeatureClass : std::uint8_t { kGround, kFacade, kRoof, kPillar, kBeam, kVertex };
inline constexpr int kFeatureClassCount = 6;

std::string_view className(FeatureClass c);
inline bool isPlanar(FeatureClass c) {
  return c == FeatureClass::kGround || c == FeatureClass::kFacade || c == FeatureClass::kRoof;
}
inline bool isLinear(FeatureClass c) { return c == FeatureClass::kPillar || c == FeatureClass::kBeam; }

// Point ids are unique over a run: the frame's sequence number in the high
// 32 bits, the index in the frame in the low 32 bits.
using FeatureId = std::uint64_t;
inline FeatureId makeFeatureId(std::uint32_t frame_seq, std::uint32_t index) {
  return (static_cast<FeatureId>(frame_seq) << 32) | index;
}
inline std::uint32_t frameOf(FeatureId id) { return static_cast<std::uint32_t>(id >> 32); }
inline std::uint32_t indexOf(FeatureId id) { return static_cast<std::uint32_t>(id & 0xffffffffu); }

struct FeaturePoint {
  Eigen::Vector3f p = Eigen::Vector3f::Zero();  // LiDAR frame at the frame's reference time
  // Unit primary direction: the normal of planar classes, the line direction
  // of linear ones, the smallest-variance axis of vertices.
  Eigen::Vector3f direction = Eigen::Vector3f::UnitZ();
  float time = 0.0f;  // capture time minus the frame's reference time, seconds
  FeatureClass cls = FeatureClass::kVertex;
  bool refined = false;  // direction set by the fusion framework (paper: d_v_mean)
};

// How the points of a frame were motion-compensated.
enum class DeskewState : std::uint8_t {
  kRaw,        // no per-point time: used as captured
  kPredicted,  // constant-velocity guess from the previous estimate
  kRefined,    // velocity from this frame's own registration
};

struct FeatureFrame {
  std::uint32_t seq = 0;
  double timestamp = 0.0;  // reference time of the points (the scan's timestamp)
  Eigen::Isometry3d T_world_lidar = Eigen::Isometry3d::Identity();  // estimate (prediction before registration)
  DeskewState deskew = DeskewState::kRaw;
  std::vector<FeaturePoint> points;

  FeatureId id(std::size_t index) const { return makeFeatureId(seq, static_cast<std::uint32_t>(index)); }
};

}  // namespace lvslam::lidar
