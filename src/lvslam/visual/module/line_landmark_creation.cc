#include "lvslam/visual/module/line_landmark_creation.h"

#include "lvslam/visual/geometry/line_projection.h"
#include "lvslam/visual/geometry/segment_trimming.h"
#include "lvslam/visual/residuals/line_reprojection.h"

namespace lvslam::visual {

namespace {
bool reprojects(const PluckerLine& line_world, const Keyframe& kf, const LineSegment& s, const Eigen::Matrix3d& K_line,
                double max_px) {
  const Eigen::Isometry3d& T = kf.T_camera_world;
  Eigen::Vector2d r;
  return LineReprojection::evaluate(T.linear(), T.translation(), line_world.vector(), s.start.homogeneous(),
                                    s.end.homogeneous(), K_line, 1.0, r, nullptr, nullptr) &&
         r.cwiseAbs().maxCoeff() <= max_px;
}
}  // namespace

std::vector<int> createLineLandmarks(VisualMap& map, int keyframe1, int keyframe2,
                                     const std::vector<LineMatch>& matches, const PinholeIntrinsics& intrinsics,
                                     const LineCreationConfig& config) {
  std::vector<int> created;
  if (keyframe1 == keyframe2) return created;
  const Keyframe& kf1 = map.keyframe(keyframe1);
  const Keyframe& kf2 = map.keyframe(keyframe2);
  Eigen::Matrix3d K;
  K << intrinsics.fx, 0.0, intrinsics.cx, 0.0, intrinsics.fy, intrinsics.cy, 0.0, 0.0, 1.0;
  const Eigen::Matrix3d K_line = lineProjectionMatrix(intrinsics.fx, intrinsics.fy, intrinsics.cx, intrinsics.cy);
  for (const LineMatch& m : matches) {
    if (m.index1 < 0 || static_cast<size_t>(m.index1) >= kf1.features.lines.size() || m.index2 < 0 ||
        static_cast<size_t>(m.index2) >= kf2.features.lines.size()) {
      continue;
    }
    if (kf1.line_landmark[m.index1] >= 0 || kf2.line_landmark[m.index2] >= 0) continue;
    const LineSegment& s1 = kf1.features.lines[m.index1];
    const LineSegment& s2 = kf2.features.lines[m.index2];
    const auto tri = triangulateLine(K, {kf1.T_camera_world, s1.start, s1.end}, {kf2.T_camera_world, s2.start, s2.end},
                                     config.triangulation);
    if (!tri || !reprojects(tri->line_world, kf1, s1, K_line, config.max_reprojection_px) ||
        !reprojects(tri->line_world, kf2, s2, K_line, config.max_reprojection_px)) {
      continue;
    }
    const auto extent = trimSegment(tri->line_world, K, {{kf1.T_camera_world, s1.start, s1.end},
                                                         {kf2.T_camera_world, s2.start, s2.end}});
    if (!extent) continue;
    const cv::Mat descriptor = kf1.features.line_descriptors.empty()
                                   ? cv::Mat()
                                   : kf1.features.line_descriptors.row(m.index1);
    const int id = map.addLineLandmark(tri->line_world, extent->start_world, extent->end_world, descriptor);
    map.addLineObservation(id, keyframe1, m.index1);
    map.addLineObservation(id, keyframe2, m.index2);
    created.push_back(id);
  }
  return created;
}

}  // namespace lvslam::visual
