// Simulator speed: one camera image, one LiDAR sweep, and single ray casts
// per scenario. Whole-sequence generation times are in docs/benchmarks.md.
#include <string>

#include <benchmark/benchmark.h>

#include "lvslam/sim/camera_renderer.h"
#include "lvslam/sim/counter_random.h"
#include "lvslam/sim/lidar_simulator.h"

namespace {

using namespace lvslam::sim;

const char* scenarioName(int index) { return index == 0 ? "room" : index == 1 ? "hall" : "gate"; }

Scenario scenarioFor(const benchmark::State& state) {
  SimOptions options;
  options.duration = 60.0;
  Scenario scenario = makeScenario(scenarioName(static_cast<int>(state.range(0))), options);
  return scenario;
}

// One 640x480 image (hall: five sub-exposures for motion blur).
void BM_RenderImage(benchmark::State& state) {
  const Scenario scenario = scenarioFor(state);
  const CameraRenderer renderer(scenario);
  double t = 5.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(renderer.renderImage(t));
    t += 1.0 / 15.0;
  }
  state.SetLabel(scenarioName(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_RenderImage)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

// One 32 x 1800 sweep, each column cast from its own pose.
void BM_ScanLidar(benchmark::State& state) {
  const Scenario scenario = scenarioFor(state);
  const LidarSimulator lidar(scenario);
  double t = 5.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(lidar.scanLidar(t));
    t += 0.1;
  }
  state.SetLabel(scenarioName(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_ScanLidar)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

// A single world ray cast through the BVH, random directions from the robot.
void BM_WorldRaycast(benchmark::State& state) {
  const Scenario scenario = scenarioFor(state);
  const Eigen::Vector3d origin = scenario.T_world_lidar(5.0).translation();
  CounterRandom rng(1, RandomStream::kScene, 0);
  for (auto _ : state) {
    const Eigen::Vector3d dir(rng.normal(), rng.normal(), rng.normal());
    benchmark::DoNotOptimize(scenario.world.raycast(origin, dir, 100.0));
  }
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(scenarioName(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_WorldRaycast)->DenseRange(0, 2);

}  // namespace
