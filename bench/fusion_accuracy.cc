// Accuracy of the fusion framework on simulated frames against the world's
// exact edges (docs/benchmarks.md, "Fusion framework"):
//   fusion_accuracy --scenario room|hall [--start S] [--duration S] [--every N]
//                   [--extrinsic-error DEG,M] [--config FILE] [--seed N]
// Runs the LiDAR odometry with the fusion step over frames simulated in
// memory; prints fusion lines per frame, endpoint distances to the matched
// true line and direction errors (median and 90th percentile).
#include <array>
#include <iostream>

#include <CLI/CLI.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <opencv2/imgcodecs.hpp>

#include "fusion/sim_fusion_harness.h"
#include "lvslam/core/error.h"
#include "lvslam/core/yaml_config.h"
#include "overlay_image.h"

int main(int argc, char** argv) {
  using namespace lvslam;
  fusion::testing::SimFusionOptions options;
  std::string extrinsic_error, config_path;
  bool per_frame = false, per_line = false;
  std::string debug_dir;
  CLI::App app{"Fusion-line accuracy on simulated frames against the exact world edges"};
  app.add_option("--scenario", options.scenario, "room | hall | gate")->default_val("room");
  app.add_option("--start", options.start, "first sweep, seconds after the sequence start")->default_val(4.0);
  app.add_option("--duration", options.duration, "seconds of camera frames measured")->default_val(10.0);
  app.add_option("--every", options.camera_every, "measure every n-th camera frame")->default_val(3);
  app.add_option("--seed", options.seed, "simulator seed")->default_val(1);
  app.add_option("--extrinsic-error", extrinsic_error, "DEG,M: the fusion gets perturbed extrinsics");
  app.add_option("--config", config_path, "YAML with lidar: and fusion: sections (config/sim.yaml)");
  app.add_flag("--per-frame", per_frame, "print one line per measured frame");
  app.add_flag("--per-line", per_line, "print every fusion line with its truth");
  app.add_option("--debug-dir", debug_dir, "write each measured frame's overlay image (as lvslam overlay draws it) here");
  CLI11_PARSE(app, argc, argv);
  if (!debug_dir.empty())
    options.on_frame = [&](const fusion::testing::SimFusionFrame& f, const cv::Mat& image, const fusion::FusionStep& step) {
      std::vector<fusion::ImageSegment> none;
      const auto& fw = step.framework();
      cv::imwrite(fmt::format("{}/frame_{:07.3f}.png", debug_dir, f.t),
                  apps::drawOverlayImage(image, fw.camera(), fw.featuresInCamera(f.output.T_world_lidar), none,
                                         f.output.result.lines));
    };
  try {
    if (!extrinsic_error.empty()) options.extrinsic_error = sim::parseExtrinsicError(extrinsic_error);
    if (!config_path.empty()) {
      const YamlConfig root = YamlConfig::loadFile(config_path);
      options.lidar = lidar::loadLidarOdometryConfig(root);
      options.fusion = fusion::loadFusionConfig(root);
    }
    const auto run = fusion::testing::runSimulatedFusion(options);
    if (per_line)
      for (const auto& f : run.frames)
        for (std::size_t i = 0; i < f.truth.size(); ++i) {
          const auto& l = f.output.result.lines[i];
          const auto& t = f.truth[i];
          fmt::print("t {:7.3f} {} depth {:5.2f}-{:5.2f} m  neighbours {:3}  surface {:.3f} {:.3f}", f.t,
                     l.kind == fusion::FusionLineKind::kPlaneIntersection ? "planar" : "linear", l.A.norm(),
                     l.B.norm(), l.neighbours, t.surface_distance[0], t.surface_distance[1]);
          if (t.edge)
            fmt::print("  edge {:.3f} {:.3f} m {:.2f} deg", t.edge->endpoint_distance[0], t.edge->endpoint_distance[1],
                       t.edge->direction_error_deg);
          fmt::print("\n");
        }
    if (per_frame)
      for (const auto& f : run.frames) {
        const auto s = eval::summarize(f.edgeMatches());
        fmt::print("t {:7.3f}  segments {:3}  lines {:3}  on edges {:3}  median endpoint {:.4f} m  median direction {:.3f} deg\n",
                   f.t, f.segments, f.output.result.lines.size(), s.lines, s.median_endpoint_distance,
                   s.median_direction_error_deg);
      }
    const auto s = run.edgeSummary();
    std::size_t segments = 0;
    std::array<int, 8> rejected{};
    for (const auto& f : run.frames) {
      segments += f.segments;
      for (std::size_t i = 0; i < rejected.size(); ++i) rejected[i] += f.output.result.rejected[i];
    }
    // In RejectReason order: none, too short, far on sphere, mixed shapes,
    // degenerate, depth inconsistent, cases disagree, out of range.
    fmt::print("rejected per reason (too short, far on sphere, mixed, degenerate, depth, disagree, range): {}\n",
               fmt::join(rejected.begin() + 1, rejected.end(), " "));
    fmt::print(
        "{} frames, {:.1f} segments/frame, {:.1f} fusion lines/frame; all lines: endpoint to true surface median "
        "{:.4f} m, p90 {:.4f} m; {} LiDAR points given d_v_mean\n",
        run.frames.size(), run.frames.empty() ? 0.0 : static_cast<double>(segments) / run.frames.size(),
        run.linesPerFrame(), run.surfaceDistanceQuantile(0.5), run.surfaceDistanceQuantile(0.9),
        run.lidar_points_changed);
    fmt::print(
        "lines on true edges: {:.1f}/frame ({} lines); endpoint to true line median {:.4f} m, p90 {:.4f} m; "
        "direction error median {:.3f} deg, p90 {:.3f} deg\n",
        run.edgeLinesPerFrame(), s.lines, s.median_endpoint_distance, s.p90_endpoint_distance,
        s.median_direction_error_deg, s.p90_direction_error_deg);
  } catch (const Error& e) {
    std::cerr << "fusion_accuracy: error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
