#pragma once
// The fields of each per-frame record, listed once for both directions of
// record_file.h's encoding: the archive writes or reads them in this order.
// The archive that writes never changes a field (it takes the record const
// and lists it through these non-const signatures).
#include "lvslam/system/frame_records.h"
#include "lvslam/system/online/online_output.h"

namespace lvslam::system {

// A record that grows a field fails here until the field is listed below
// (and the size updated): a field left out would come back as its default.
static_assert(sizeof(visual::VisualFrameResult) == 1168 && sizeof(VisualFrameRecord) == 1520 &&
                  sizeof(LidarFrameRecord) == 544 && sizeof(FrameOutput) == 576 &&
                  sizeof(ScanRecord) == 128 && sizeof(GateEvent) == 64,
              "a per-frame record changed: list its fields in record_fields.h");

template <typename A>
void fields(A& a, StampedPose& p) {
  a(p.t), a(p.T_world_frame);
}

template <typename A>
void fields(A& a, visual::TrackedPointObservation& o) {
  a(o.landmark), a(o.pixel), a(o.inv_sigma2);
}

template <typename A>
void fields(A& a, visual::TrackedLineObservation& o) {
  a(o.landmark), a(o.start), a(o.end);
}

template <typename A>
void fields(A& a, visual::TrackedObservations& o) {
  a(o.points), a(o.lines);
}

template <typename A>
void fields(A& a, visual::FrameHealth& h) {
  a(h.tracked_points), a(h.tracked_lines), a(h.inlier_ratio), a(h.brightness), a(h.contrast), a(h.keypoints),
      a(h.segments);
}

template <typename A>
void fields(A& a, visual::VisualFusionInfo& f) {
  a(f.pose_information), a(f.T_world_odom), a(f.anchor_time), a(f.T_new_old);
}

template <typename A>
void fields(A& a, visual::VisualReplayData& r) {
  a(r.reference_keyframe), a(r.T_keyframe_camera), a(r.observations);
}

template <typename A>
void fields(A& a, visual::VisualFrameResult& r) {
  a(r.timestamp), a(r.state), a(r.pose_valid), a(r.T_world_camera), a(r.map_id), a(r.keyframe), a(r.metric),
      a(r.initial_reference), a(r.initial_reference_keyframe), a(r.health), a(r.fusion), a(r.replay);
}

template <typename A>
void fields(A& a, VisualFrameRecord& v) {
  a(v.t), a(v.result), a(v.T_world_camera_final), a(v.initial_reference_final), a(v.fusion_lines_added),
      a(v.keypoint_depths), a(v.extract_ms), a(v.hints_ms), a(v.track_ms), a(v.fusion_apply_ms);
}

template <typename A>
void fields(A& a, CameraLine& l) {
  a(l.A), a(l.B);
}

template <typename A>
void fields(A& a, LidarFrameRecord& l) {
  a(l.t), a(l.T_odom_lidar), a(l.pose_reliable), a(l.information), a(l.degenerate), a(l.registration),
      a(l.fusion_lines), a(l.lidar_features), a(l.lidar_points_refined), a(l.keypoint_depths), a(l.fusion_ms);
}

template <typename A>
void fields(A& a, ScanRecord& s) {
  a(s.t), a(s.status), a(s.features), a(s.correspondences), a(s.features_per_class), a(s.iterations),
      a(s.prepare_ms), a(s.register_ms);
}

template <typename A>
void fields(A& a, GateEvent& g) {
  a(g.t), a(g.source), a(g.chi_square), a(g.threshold), a(g.reason);
}

template <typename A>
void fields(A& a, FrameOutput& f) {
  a(f.t), a(f.T_world_camera), a(f.source), a(f.problem), a(f.fused), a(f.gated), a(f.visual_chi_square_per_dof),
      a(f.lidar_noise_scale), a(f.visual_noise_scale), a(f.covariance), a(f.latency_ms);
}

}  // namespace lvslam::system
