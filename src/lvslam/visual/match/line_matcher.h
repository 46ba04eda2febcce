#pragma once
// LBD line segment matching: frame to frame (triangulation of new lines) and
// projected map lines to a frame (tracking). Descriptor distance with a ratio
// test, gated by geometry (angle of the segments, position), each segment
// used once.
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "lvslam/visual/feature/feature_frame.h"

namespace lvslam::visual {

struct LineMatcherConfig {
  int max_distance = 70;         // Hamming of 256-bit LBD
  double ratio = 0.8;            // best < ratio * second best
  double max_angle_deg = 15.0;   // direction difference (segments are unoriented)
  double max_offset_px = 60.0;   // frame to frame: midpoint displacement
  double max_line_distance_px = 10.0;  // by projection: endpoints to the projected line
};

struct LineMatch {
  int index1 = -1, index2 = -1;
  int distance = 0;
};

std::vector<LineMatch> matchLines(const FeatureFrame& a, const FeatureFrame& b, const LineMatcherConfig& config = {});

// A map line predicted in the frame.
struct ProjectedLine {
  Eigen::Vector2d start = Eigen::Vector2d::Zero(), end = Eigen::Vector2d::Zero();  // projected endpoints
  cv::Mat descriptor;  // 1 x 32 CV_8U
};

std::vector<LineMatch> matchLinesByProjection(const std::vector<ProjectedLine>& projected, const FeatureFrame& frame,
                                              const LineMatcherConfig& config = {});

// Angle between two undirected segments, in [0, 90] degrees.
double segmentAngleDeg(const Eigen::Vector2d& a0, const Eigen::Vector2d& a1, const Eigen::Vector2d& b0,
                       const Eigen::Vector2d& b1);

}  // namespace lvslam::visual
