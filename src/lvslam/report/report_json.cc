#include "lvslam/report/report_json.h"

#include "lvslam/eval/json_writer.h"
#include "lvslam/report/number_arrays.h"

namespace lvslam::report {

using eval::JsonObject;

std::string trajectoryJson(const std::string& name, const Trajectory& trajectory, std::size_t max_poses) {
  std::vector<double> t, p, q;
  const std::size_t stride = trajectory.size() > max_poses ? (trajectory.size() + max_poses - 1) / max_poses : 1;
  for (std::size_t i = 0; i < trajectory.size(); i += stride) {
    const StampedPose& pose = trajectory[i];
    const Eigen::Vector3d position = pose.T_world_frame.translation();
    const Eigen::Quaterniond rotation(pose.T_world_frame.rotation());
    t.push_back(pose.t);
    p.insert(p.end(), {position.x(), position.y(), position.z()});
    q.insert(q.end(), {rotation.x(), rotation.y(), rotation.z(), rotation.w()});
  }
  return JsonObject()
      .addString("name", name)
      .addRaw("t", fixedArray(t, 4))
      .addRaw("p", fixedArray(p, 4))
      .addRaw("q", fixedArray(q, 4))
      .str();
}

namespace {

std::string statsJson(const eval::ErrorStatistics& s) {
  return JsonObject()
      .addCount("count", s.count)
      .addNumber("rmse", s.rmse)
      .addNumber("mean", s.mean)
      .addNumber("median", s.median)
      .addNumber("std", s.std_dev)
      .addNumber("min", s.min)
      .addNumber("max", s.max)
      .addNumber("sse", s.sse)
      .str();
}

}  // namespace

std::string errorsJson(const TrajectoryErrors& errors) {
  const Eigen::Matrix3d& R = errors.T_gt_est.R;
  std::string series = "[";
  for (const ErrorSeries& s : errors.series) {
    if (series.size() > 1) series += ",";
    series += JsonObject()
                  .addString("name", s.name)
                  .addString("unit", s.unit)
                  .addRaw("t", fixedArray(s.t, 4))
                  .addRaw("v", fixedArray(s.values, 5))
                  .addRaw("stats", statsJson(s.stats))
                  .str();
  }
  return JsonObject()
      .addString("alignment", eval::alignmentName(errors.alignment))
      .addNumber("scale", errors.T_gt_est.scale)
      .addRaw("R", fixedArray({R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2)}, 9))
      .addRaw("t", fixedArray({errors.T_gt_est.t.x(), errors.T_gt_est.t.y(), errors.T_gt_est.t.z()}, 6))
      .addRaw("series", series + "]")
      .str();
}

std::string mapJson(const DecimatedMap& map, std::size_t points_total) {
  std::vector<double> p, cls;
  p.reserve(3 * map.points.size());
  for (const PlyPoint& q : map.points) {
    p.insert(p.end(), {q.p.x(), q.p.y(), q.p.z()});
    cls.push_back(q.intensity);
  }
  return JsonObject()
      .addCount("points_total", points_total)
      .addNumber("voxel_m", map.voxel_m)
      .addRaw("p", fixedArray(p, 2))
      .addRaw("cls", fixedArray(cls, 0))
      .str();
}

std::string linesJson(const std::vector<PlySegment>& segments) {
  std::vector<double> p, rgb;
  for (const PlySegment& s : segments) {
    p.insert(p.end(), {s.a.x(), s.a.y(), s.a.z(), s.b.x(), s.b.y(), s.b.z()});
    rgb.insert(rgb.end(), {double(s.r), double(s.g), double(s.b_colour)});
  }
  return JsonObject().addRaw("p", fixedArray(p, 3)).addRaw("rgb", fixedArray(rgb, 0)).str();
}

}  // namespace lvslam::report
