// The fusion framework per camera frame on a realistic frame: the simulated
// room, five accumulated 32-ring scans' features from the real LiDAR
// odometry and the LSD segments (~100) of the rendered image.
#include <benchmark/benchmark.h>

#include "lvslam/fusion/fusion_step.h"
#include "lvslam/fusion/lidar_bridge.h"
#include "lvslam/sim/camera_renderer.h"
#include "lvslam/sim/lidar_simulator.h"
#include "lvslam/sim/scenario.h"

namespace {

using namespace lvslam;

struct RealisticFrame {
  sim::Scenario scenario = sim::makeScenario("room", {});
  lidar::LidarOdometry odometry{lidar::LidarOdometryConfig{}};
  fusion::FusionStep step{scenario.camera.camera, scenario.rig.T_camera_lidar(), fusion::FusionConfig{}};
  std::vector<fusion::ImageSegment> segments;
  double t_camera = 0.0;

  RealisticFrame() {
    const sim::LidarSimulator lidar(scenario);
    const double t0 = scenario.lidar.start_offset + 5.0;
    for (int k = 0; k < 4; ++k) odometry.process(lidar.scanLidar(t0 + k * lidar.sweepDuration()));
    const double t_last = t0 + 4 * lidar.sweepDuration();
    odometry.prepare(lidar.scanLidar(t_last));
    step.loadScans(odometry);
    t_camera = t_last + 0.05;
    visual::LineExtractorConfig config;
    config.compute_descriptors = false;
    config.min_length_ratio = 30.0 / 480.0;
    visual::LineExtractor extractor(config);
    std::vector<visual::RawSegment> raw;
    cv::Mat unused;
    extractor.extract(sim::CameraRenderer(scenario).renderImage(t_camera), raw, unused);
    segments = fusion::toImageSegments(raw);
  }
};

RealisticFrame& frame() {
  static RealisticFrame f;  // built once: the simulation is not what is measured
  return f;
}

// Alignment to the camera time, spherical KD-tree, association and line
// reconstruction for every segment: FusionFramework::process.
void BM_FusionProcessFrame(benchmark::State& state) {
  RealisticFrame& f = frame();
  const Eigen::Isometry3d T_world_lidar = f.odometry.poseAt(f.t_camera);
  std::size_t lines = 0;
  for (auto _ : state) {
    const auto result = f.step.framework().process(f.t_camera, T_world_lidar, f.segments);
    lines = result.lines.size();
    benchmark::DoNotOptimize(result);
  }
  state.counters["features"] = static_cast<double>(f.step.framework().featuresInCamera(T_world_lidar).size());
  state.counters["segments"] = static_cast<double>(f.segments.size());
  state.counters["lines"] = static_cast<double>(lines);
}
BENCHMARK(BM_FusionProcessFrame)->Unit(benchmark::kMillisecond);

// Per LiDAR scan: the five frames' features moved to the world (loadScans).
void BM_FusionLoadScans(benchmark::State& state) {
  RealisticFrame& f = frame();
  for (auto _ : state) f.step.loadScans(f.odometry);
}
BENCHMARK(BM_FusionLoadScans)->Unit(benchmark::kMillisecond);

}  // namespace
