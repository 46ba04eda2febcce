// How precisely the ORB front end finds the same corner again, against the
// simulator's exact geometry (docs/history/2026-11-fusion-sessions.md, "The
// visual step"):
//   keypoint_accuracy --scenario room|hall|gate [--seed N] [--gap FRAMES]
// For camera frames every 5 s, each keypoint on a smooth surface is carried
// by its true depth and the true motion into the image `gap` frames later;
// the keypoint there with the nearest ORB descriptor (same level +-1, within
// 8 px, Hamming distance <= 50) is its match. Prints, per pyramid level, the
// distance between the match and the true projection: it holds both
// detections' localisation error, so one detection's is about 1/sqrt(2) of it.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <opencv2/core.hpp>

#include "lvslam/core/error.h"
#include "lvslam/sim/camera_renderer.h"
#include "lvslam/visual/feature/orb_extractor.h"

namespace {

using namespace lvslam;

constexpr double kSearchRadiusPx = 8.0;
constexpr int kMaxHamming = 50;
constexpr int kSmoothRadiusPx = 2;
constexpr float kSmoothDepthRatio = 0.02f;  // depth spread over the window / depth

// The true depth at a keypoint lying on one smooth surface (no depth edge
// within kSmoothRadiusPx), else 0.
float smoothDepth(const cv::Mat& depth, int x, int y) {
  if (x < kSmoothRadiusPx || y < kSmoothRadiusPx || x + kSmoothRadiusPx >= depth.cols ||
      y + kSmoothRadiusPx >= depth.rows)
    return 0.0f;
  const cv::Mat window = depth(cv::Rect(x - kSmoothRadiusPx, y - kSmoothRadiusPx, 2 * kSmoothRadiusPx + 1,
                                        2 * kSmoothRadiusPx + 1));
  double lo = 0.0, hi = 0.0;
  cv::minMaxLoc(window, &lo, &hi);
  if (!(lo > 0.0) || hi - lo > kSmoothDepthRatio * lo) return 0.0f;
  return depth.at<float>(y, x);
}

int bestMatch(const cv::KeyPoint& kp, const cv::Mat& descriptor, const Eigen::Vector2d& predicted,
              const std::vector<cv::KeyPoint>& candidates, const cv::Mat& descriptors) {
  int best = -1, best_distance = kMaxHamming + 1;
  for (std::size_t j = 0; j < candidates.size(); ++j) {
    if (std::abs(candidates[j].octave - kp.octave) > 1) continue;
    if (std::hypot(candidates[j].pt.x - predicted.x(), candidates[j].pt.y - predicted.y()) > kSearchRadiusPx) continue;
    const int d = static_cast<int>(cv::norm(descriptor, descriptors.row(static_cast<int>(j)), cv::NORM_HAMMING));
    if (d < best_distance) best_distance = d, best = static_cast<int>(j);
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  std::string scenario = "hall";
  std::uint64_t seed = 1;
  int gap = 1;
  CLI::App app{"ORB keypoint localisation against the simulator's exact geometry"};
  app.add_option("--scenario", scenario, "room | hall | gate")->default_val("hall");
  app.add_option("--seed", seed, "simulator seed")->default_val(1);
  app.add_option("--gap", gap, "frames between the two images")->default_val(1)->check(CLI::Range(1, 30));
  CLI11_PARSE(app, argc, argv);
  try {
    sim::SimOptions options;
    options.duration = 60.0;
    options.seed = seed;
    const sim::Scenario sc = sim::makeScenario(scenario, options);
    const sim::CameraRenderer renderer(sc);
    const PinholeCamera& camera = sc.camera.camera;
    visual::OrbExtractor orb(visual::OrbExtractorConfig{});
    const double dt = gap / sc.camera.rate_hz;
    std::vector<std::vector<double>> errors(orb.config().num_levels);
    for (double t = 5.0; t < 55.0; t += 5.0) {
      const cv::Mat depth = renderer.renderDepth(t);
      std::vector<cv::KeyPoint> ka, kb;
      cv::Mat da, db;
      orb.extract(renderer.renderImage(t), ka, da);
      orb.extract(renderer.renderImage(t + dt), kb, db);
      const Eigen::Isometry3d T_b_a = sc.T_world_camera(t + dt).inverse() * sc.T_world_camera(t);
      for (std::size_t i = 0; i < ka.size(); ++i) {
        const float z = smoothDepth(depth, cvRound(ka[i].pt.x), cvRound(ka[i].pt.y));
        if (z <= 0.0f) continue;
        const Eigen::Vector3d ray = camera.unproject(Eigen::Vector2d(ka[i].pt.x, ka[i].pt.y));
        const auto predicted = camera.project(T_b_a * (ray / ray.z() * z));
        if (!predicted) continue;
        const int j = bestMatch(ka[i], da.row(static_cast<int>(i)), *predicted, kb, db);
        if (j < 0) continue;
        errors[ka[i].octave].push_back(std::hypot(kb[j].pt.x - predicted->x(), kb[j].pt.y - predicted->y()));
      }
    }
    std::cout << fmt::format("{} seed {}, {} frame(s) apart: matched keypoint to true projection, px\n", scenario,
                             seed, gap);
    std::cout << "level | matches | median | rms | p90 | median / level scale\n";
    for (std::size_t level = 0; level < errors.size(); ++level) {
      std::vector<double>& e = errors[level];
      if (e.empty()) continue;
      std::sort(e.begin(), e.end());
      double sum_sq = 0.0;
      for (const double v : e) sum_sq += v * v;
      const double median = e[e.size() / 2];
      std::cout << fmt::format("{} | {} | {:.2f} | {:.2f} | {:.2f} | {:.2f}\n", level, e.size(), median,
                               std::sqrt(sum_sq / static_cast<double>(e.size())), e[e.size() * 9 / 10],
                               median / orb.pyramid().scale[level]);
    }
  } catch (const Error& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  return 0;
}
