#include "lvslam/visual/geometry/segment_trimming.h"

#include <limits>

#include "lvslam/visual/geometry/line_projection.h"

namespace lvslam::visual {

std::optional<TrimmedSegment> trimSegment(const PluckerLine& line_world, const Eigen::Matrix3d& K,
                                          const std::vector<SegmentObservation>& observations) {
  if (!line_world.isValid(1e-6)) return std::nullopt;
  const PluckerLine unit = line_world.normalized();
  const Eigen::Vector3d origin = unit.closestPointToOrigin();
  double s_min = std::numeric_limits<double>::infinity(), s_max = -s_min;
  for (const SegmentObservation& o : observations) {
    const auto ends = segmentEndpointsOnLine(unit.transformed(o.T_camera_world), K, o.start, o.end);
    if (!ends) continue;
    const Eigen::Isometry3d T_world_camera = o.T_camera_world.inverse();
    for (const Eigen::Vector3d& p_camera : {ends->start, ends->end}) {
      const double s = unit.d.dot(T_world_camera * p_camera - origin);  // position along the line
      s_min = std::min(s_min, s);
      s_max = std::max(s_max, s);
    }
  }
  if (!(s_max >= s_min)) return std::nullopt;
  return TrimmedSegment{origin + s_min * unit.d, origin + s_max * unit.d};
}

}  // namespace lvslam::visual
