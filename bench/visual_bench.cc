// Visual subsystem micro-benchmarks: feature extraction on a 640x480 image
// (ORB on the grid, LSD with length rejection, LBD), motion-only pose
// optimisation and a local bundle adjustment window.
#include <random>

#include <benchmark/benchmark.h>
#include <opencv2/imgproc.hpp>

#include "lvslam/visual/feature/feature_extractor.h"
#include "lvslam/visual/optimize/bundle_adjustment.h"
#include "lvslam/visual/optimize/pose_optimization.h"
#include "visual/synthetic_images.h"
#include "visual/synthetic_scene.h"

namespace lvslam::visual {
namespace {

// Texture everywhere plus 25 long straight edges, like a furnished room.
cv::Mat benchImage() {
  cv::Mat img = testing::texturedImage(640, 480, 5);
  cv::RNG rng(9);
  for (int i = 0; i < 25; ++i) {
    const cv::Point a(rng.uniform(0, 640), rng.uniform(0, 480)), b(rng.uniform(0, 640), rng.uniform(0, 480));
    cv::line(img, a, b, cv::Scalar(rng.uniform(0, 2) * 255), 3);
  }
  return img;
}

PinholeCamera vga() { return PinholeCamera(640, 480, 450.0, 450.0, 319.5, 239.5); }

void BM_FeatureExtraction(benchmark::State& state) {
  FeatureExtractorConfig config;
  config.extract_lines = state.range(0) != 0;
  FeatureExtractor extractor(config, vga());
  const ImageFrame frame{0.0, benchImage()};
  size_t points = 0, lines = 0;
  for (auto _ : state) {
    const FeatureFrame f = extractor.extract(frame);
    points = f.keypoints.size();
    lines = f.lines.size();
    benchmark::DoNotOptimize(f.descriptors.data);
  }
  state.counters["points"] = static_cast<double>(points);
  state.counters["lines"] = static_cast<double>(lines);
}
BENCHMARK(BM_FeatureExtraction)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

void BM_LineExtraction(benchmark::State& state) {
  LineExtractorConfig config;
  config.compute_descriptors = state.range(0) != 0;
  config.descriptor_octave = static_cast<int>(state.range(1));  // 0: LBD at full resolution
  LineExtractor lines(config);
  const cv::Mat img = benchImage();
  std::vector<RawSegment> segments;
  cv::Mat desc;
  for (auto _ : state) {
    lines.extract(img, segments, desc);
    benchmark::DoNotOptimize(segments.data());
  }
  state.counters["lines"] = static_cast<double>(segments.size());
}
// Args: {descriptors on, LBD octave}.
BENCHMARK(BM_LineExtraction)->Args({1, 1})->Args({1, 0})->Args({0, 1})->Unit(benchmark::kMillisecond);

void BM_PoseOptimization(benchmark::State& state) {
  const testing::SyntheticScene s = testing::makeScene(2, 600, 60, 0.2, 1);
  const Eigen::Isometry3d T = s.T_camera_world[1];
  std::mt19937 rng(2);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<PosePointObservation> points;
  std::vector<PoseLineObservation> lines;
  for (const auto& p : s.points) {
    const Eigen::Vector3d uvz = s.project(T, p);
    if (s.visible(uvz)) points.push_back({p, uvz.head<2>() + Eigen::Vector2d(noise(rng), noise(rng)), 1.0});
  }
  for (const auto& seg : s.segments) {
    const Eigen::Vector3d a = s.project(T, seg.a), b = s.project(T, seg.b);
    if (s.visible(a) && s.visible(b)) lines.push_back({testing::lineOf(seg), a.head<2>(), b.head<2>(), 1.0});
  }
  Vector6d xi;
  xi << 0.05, 0.02, -0.03, 0.01, 0.01, -0.02;
  for (auto _ : state) {
    const PoseOptimizationResult r = optimizePose(expSE3(xi) * T, points, lines, s.K);
    benchmark::DoNotOptimize(r.T_camera_world);
  }
  state.counters["points"] = static_cast<double>(points.size());
  state.counters["lines"] = static_cast<double>(lines.size());
}
BENCHMARK(BM_PoseOptimization)->Unit(benchmark::kMillisecond);

void BM_LocalBundleAdjustment(benchmark::State& state) {
  const testing::SyntheticScene s = testing::makeScene(static_cast<int>(state.range(0)), 400, 50, 0.1, 3);
  BundleAdjustmentProblem truth;
  truth.intrinsics = s.K;
  std::mt19937 rng(4);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (size_t k = 0; k < s.T_camera_world.size(); ++k) truth.keyframes.push_back({s.T_camera_world[k], k < 2, std::nullopt});
  for (const auto& p : s.points) truth.points.push_back({p + 0.02 * Eigen::Vector3d(noise(rng), noise(rng), noise(rng)), false});
  for (const auto& seg : s.segments) truth.lines.push_back({testing::lineOf(seg), seg.b - seg.a, false});
  for (size_t k = 0; k < s.T_camera_world.size(); ++k) {
    for (size_t i = 0; i < s.points.size(); ++i) {
      const Eigen::Vector3d uvz = s.project(s.T_camera_world[k], s.points[i]);
      if (s.visible(uvz)) {
        truth.point_observations.push_back({static_cast<int>(k), static_cast<int>(i),
                                            uvz.head<2>() + Eigen::Vector2d(noise(rng), noise(rng)), 1.0});
      }
    }
    for (size_t j = 0; j < s.segments.size(); ++j) {
      const Eigen::Vector3d a = s.project(s.T_camera_world[k], s.segments[j].a);
      const Eigen::Vector3d b = s.project(s.T_camera_world[k], s.segments[j].b);
      if (s.visible(a) && s.visible(b)) {
        truth.line_observations.push_back({static_cast<int>(k), static_cast<int>(j), a.head<2>(), b.head<2>(), 1.0});
      }
    }
  }
  for (auto _ : state) {
    BundleAdjustmentProblem p = truth;
    const BundleAdjustmentResult r = runBundleAdjustment(p);
    benchmark::DoNotOptimize(r.final_cost);
  }
  state.counters["point_obs"] = static_cast<double>(truth.point_observations.size());
  state.counters["line_obs"] = static_cast<double>(truth.line_observations.size());
}
BENCHMARK(BM_LocalBundleAdjustment)->Arg(10)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace lvslam::visual
