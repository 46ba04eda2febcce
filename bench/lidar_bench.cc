// LiDAR odometry speed on full-size 32-ring sweeps (32 x 1800 = 57,600 rays)
// of the synthetic hall of tests/lidar: scans per second of prepare +
// register, and of the feature extraction alone. CPU time is the whole
// process's (TBB workers included), so it is the cost per scan on one core.
#include <benchmark/benchmark.h>

#include "lidar/synthetic_lidar.h"
#include "lvslam/lidar/feature_extraction.h"
#include "lvslam/lidar/lidar_odometry.h"
#include "lvslam/lidar/preprocess.h"

namespace {

using namespace lvslam;

std::vector<LidarScan> driveScans(int count) {
  testing::SyntheticSensor sensor;
  sensor.columns = 1800;
  sensor.range_noise = 0.01;
  std::mt19937 rng(3);
  std::vector<LidarScan> scans;
  for (int i = 0; i < count; ++i)
    scans.push_back(testing::castScan(testing::structuredRoom(), testing::drivePose, 0.1 * i, sensor, &rng));
  return scans;
}

void BM_LidarOdometryProcess(benchmark::State& state) {
  const std::vector<LidarScan> scans = driveScans(30);
  std::size_t processed = 0;
  for (auto _ : state) {
    state.PauseTiming();
    lidar::LidarOdometry odometry{lidar::LidarOdometryConfig{}};
    state.ResumeTiming();
    for (const LidarScan& scan : scans) benchmark::DoNotOptimize(odometry.process(scan));
    processed += scans.size();
  }
  state.counters["scans_per_s"] = benchmark::Counter(static_cast<double>(processed), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_LidarOdometryProcess)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();

void BM_LidarFeatureExtraction(benchmark::State& state) {
  const std::vector<LidarScan> scans = driveScans(1);
  const lidar::LidarOdometryConfig config;
  for (auto _ : state) {
    const auto points = lidar::cropAndDownsample(scans.front(), config.preprocess, config.features.neighbour_radius);
    benchmark::DoNotOptimize(lidar::extractFeatures(points, config.ground, config.features));
  }
  state.counters["scans_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_LidarFeatureExtraction)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();

}  // namespace
