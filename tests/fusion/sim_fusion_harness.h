#pragma once
// Runs the LiDAR odometry with the fusion step over simulated frames built in
// memory (no folder), and measures every fusion line against the world's
// exact edges with the ground-truth camera pose. Shared by the accuracy test
// and the measurement program bench/fusion_accuracy.cc.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "lvslam/fusion/fusion_step.h"
#include "lvslam/eval/line_accuracy.h"
#include "lvslam/lidar/lidar_config.h"
#include "lvslam/sim/sim_options.h"
#include "lvslam/visual/feature/line_extractor.h"

namespace lvslam::fusion::testing {

struct SimFusionOptions {
  std::string scenario = "room";
  std::uint64_t seed = 1;
  double start = 4.0;     // seconds after the sequence start of the first sweep used
  double duration = 1.0;  // seconds of camera frames measured, after the warm-up
  int warmup_scans = 4;   // scans registered before the first measured camera frame
  int camera_every = 1;   // measure every n-th camera frame
  std::optional<sim::ExtrinsicError> extrinsic_error;  // the fusion is given the perturbed extrinsics
  FusionConfig fusion;
  lidar::LidarOdometryConfig lidar;
  visual::LineExtractorConfig lines = defaultLines();
  // Called for every measured frame with its image (e.g. to draw it).
  std::function<void(const struct SimFusionFrame&, const cv::Mat& image, const FusionStep&)> on_frame;

  // LSD as the visual subsystem runs it, without descriptors, down to the
  // fusion's shortest segment (30 px).
  static visual::LineExtractorConfig defaultLines();
};

// The truth about one fusion line. Its image segment is an "edge segment"
// when a true edge, projected with the true camera pose, runs along it (both
// endpoints within 3 px of it, 3 deg); then `edge` is the 3D match to the
// nearest true edge. Other segments are texture (tile grout, bricks, poster
// borders printed on a plane): no edge to compare with, but like every line
// they must lie on a true surface.
struct LineTruth {
  std::optional<eval::LineMatch> edge;
  double surface_distance[2] = {0, 0};  // metres, A and B to the nearest true surface
};

struct SimFusionFrame {
  double t = 0.0;  // seconds after the sequence start
  std::size_t segments = 0;
  FusionFrameOutput output;
  std::vector<LineTruth> truth;  // one per fusion line, same order
  std::vector<eval::LineMatch> edgeMatches() const;
};

struct SimFusionRun {
  std::vector<SimFusionFrame> frames;
  std::vector<eval::TrueSegment> edges;  // the world's edges
  std::size_t lidar_points_changed = 0;
  eval::AccuracySummary edgeSummary() const;  // over the lines of edge segments
  double linesPerFrame() const;
  double edgeLinesPerFrame() const;
  double surfaceDistanceQuantile(double q) const;  // over all lines' endpoints
};

SimFusionRun runSimulatedFusion(const SimFusionOptions& options);

}  // namespace lvslam::fusion::testing
