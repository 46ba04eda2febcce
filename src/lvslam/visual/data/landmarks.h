#pragma once
// Map landmarks of the visual subsystem: 3D points and 3D lines (Plücker),
// each with the keyframe features that observe it.
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "lvslam/core/plucker_line.h"

namespace lvslam::visual {

// A landmark seen by feature `index` of keyframe `keyframe` (both ids).
struct Observation {
  int keyframe = -1;
  int index = -1;
};

struct PointLandmark {
  int id = -1;
  Eigen::Vector3d p_world = Eigen::Vector3d::Zero();
  cv::Mat descriptor;  // 1 x 32 ORB of a representative observation
  std::vector<Observation> observations;
};

struct LineLandmark {
  int id = -1;
  PluckerLine line_world;
  // Segment extent on the infinite line (trimmed by the back end).
  Eigen::Vector3d start_world = Eigen::Vector3d::Zero(), end_world = Eigen::Vector3d::Zero();
  cv::Mat descriptor;  // 1 x 32 LBD
  std::vector<Observation> observations;
  // Direction d_fu the fusion framework reconstructed for this line, which
  // adds the line direction residual in BA (Cao et al., Sec. III-D).
  std::optional<Eigen::Vector3d> fusion_direction;
  // The landmark was created from a fusion line (LiDAR depth), not by
  // two-view triangulation; its outlier test is looser (0.2 instead of 0.1).
  bool from_fusion = false;
};

}  // namespace lvslam::visual
