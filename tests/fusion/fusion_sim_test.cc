// The fusion framework on whole simulated frames (room), measured against the
// simulator's exact edges with the ground-truth camera pose.
#include <gtest/gtest.h>

#include "fusion/sim_fusion_harness.h"

namespace lvslam::fusion::testing {
namespace {

struct EdgeKinds {
  int vertical = 0;      // door / window frames, shelf sides, pillar edges
  int low_horizontal = 0;  // wall-floor boundaries, baseboards (below 0.3 m)
};

EdgeKinds kindsOfMatchedEdges(const SimFusionRun& run) {
  EdgeKinds kinds;
  for (const auto& f : run.frames)
    for (const eval::LineMatch& m : f.edgeMatches()) {
      const eval::TrueSegment& e = run.edges[m.segment];
      const Eigen::Vector3d d = (e.b - e.a).normalized();
      if (std::abs(d.z()) > 0.95) ++kinds.vertical;
      if (std::abs(d.z()) < 0.05 && std::max(e.a.z(), e.b.z()) < 0.3) ++kinds.low_horizontal;
    }
  return kinds;
}

SimFusionOptions roomFrames() {
  SimFusionOptions options;
  options.scenario = "room";
  options.start = 4.0;
  options.duration = 0.5;  // 7-8 camera frames after four warm-up scans
  return options;
}

TEST(FusionOnSimulatedFrames, WholeFrameYieldsFusionLinesOnTrueDoorFramesAndWallEdgesWithinBounds) {
  const SimFusionRun run = runSimulatedFusion(roomFrames());
  ASSERT_GE(run.frames.size(), 6u);
  const eval::AccuracySummary edges = run.edgeSummary();
  std::cout << "room: " << run.linesPerFrame() << " fusion lines/frame, " << run.edgeLinesPerFrame()
            << " on true edges; endpoint median " << edges.median_endpoint_distance << " m, direction median "
            << edges.median_direction_error_deg << " deg; surface median " << run.surfaceDistanceQuantile(0.5)
            << " m\n";
  EXPECT_GE(run.edgeLinesPerFrame(), 3.0);
  EXPECT_LT(edges.median_endpoint_distance, 0.05);
  EXPECT_LT(edges.median_direction_error_deg, 2.0);
  // Every line, texture lines included, lies on a true surface.
  EXPECT_LT(run.surfaceDistanceQuantile(0.5), 0.05);
  const EdgeKinds kinds = kindsOfMatchedEdges(run);
  EXPECT_GT(kinds.vertical, 0);
  EXPECT_GT(kinds.low_horizontal, 0);
}

// NOT MET YET (disabled, not loosened): on these frames a 1 deg / 3 cm
// extrinsic error moves the fusion lines' endpoints 17 cm (median) off the
// true edges; over 3 s of room frames it is 8 cm (docs/benchmarks.md,
// "Accuracy against the simulator's exact geometry"). The
// planar case takes the LiDAR plane as given, and a 1 deg rotation shifts a
// wall 3-5 m away by 5-9 cm before any other error.
TEST(FusionOnSimulatedFrames, DISABLED_ExtrinsicErrorOfOneDegreeAndThreeCentimetresAtMostDoublesTheErrors) {
  SimFusionOptions options = roomFrames();
  options.extrinsic_error = sim::ExtrinsicError{1.0, 0.03};
  const SimFusionRun run = runSimulatedFusion(options);
  const eval::AccuracySummary edges = run.edgeSummary();
  std::cout << "room, extrinsic error 1 deg / 3 cm: " << run.edgeLinesPerFrame()
            << " lines/frame on true edges; endpoint median " << edges.median_endpoint_distance
            << " m, direction median " << edges.median_direction_error_deg << " deg\n";
  EXPECT_GE(run.edgeLinesPerFrame(), 2.0);
  EXPECT_LT(edges.median_endpoint_distance, 2 * 0.05);
  EXPECT_LT(edges.median_direction_error_deg, 2 * 2.0);
}

}  // namespace
}  // namespace lvslam::fusion::testing
