#pragma once
// A 4 s simulated room sequence rendered in memory with exact poses and
// depth, the input of the VisualSlam tests. Rendered once per test process
// and shared by every fixture derived from RenderedRoomTest.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include <opencv2/core.hpp>

#include "lvslam/core/image_frame.h"
#include "lvslam/core/trajectory.h"
#include "lvslam/eval/evaluate.h"
#include "lvslam/sim/camera_renderer.h"
#include "lvslam/sim/scenario.h"
#include "lvslam/visual/visual_slam.h"

namespace lvslam::visual::testing {

class RenderedRoomTest : public ::testing::Test {
 protected:
  struct RenderedFrame {
    ImageFrame image;
    cv::Mat depth;  // CV_32F, exact
    Eigen::Isometry3d T_world_camera;
  };

  static constexpr double kDuration = 4.0;

  // Not torn down per suite: rendering takes seconds and both test files'
  // suites read the same frames.
  static void SetUpTestSuite() {
    if (frames_) return;
    sim::SimOptions options;
    options.scenario = "room";
    options.duration = kDuration;
    scenario_ = std::make_unique<sim::Scenario>(sim::makeScenario(options));
    const sim::CameraRenderer renderer(*scenario_);
    frames_ = std::make_unique<std::vector<RenderedFrame>>();
    for (double t = 0.0; t < kDuration; t += 1.0 / scenario_->camera.rate_hz)
      frames_->push_back({{t, renderer.renderImage(t)}, renderer.renderDepth(t), scenario_->T_world_camera(t)});
  }

  // Exact depth on a 4-pixel grid, the stand-in for projected LiDAR points.
  static std::vector<PixelDepth> depthHints(const cv::Mat& depth) {
    std::vector<PixelDepth> hints;
    for (int v = 0; v < depth.rows; v += 4)
      for (int u = 0; u < depth.cols; u += 4)
        if (depth.at<float>(v, u) > 0.0f) hints.push_back({{u, v}, depth.at<float>(v, u)});
    return hints;
  }

  // Feeds frames [begin, end) and collects the tracked poses.
  static void run(VisualSlam& slam, size_t begin, size_t end, Trajectory& estimate, Trajectory& truth,
                  std::vector<VisualFrameResult>* results = nullptr) {
    for (size_t i = begin; i < end; ++i) {
      const RenderedFrame& f = (*frames_)[i];
      if (slam.needsDepthHints()) slam.setDepthHints(depthHints(f.depth));
      const VisualFrameResult r = slam.track(f.image);
      if (results) results->push_back(r);
      if (!r.pose_valid) continue;
      estimate.push_back({r.timestamp, r.T_world_camera});
      truth.push_back({r.timestamp, f.T_world_camera});
    }
  }

  static const PinholeCamera& camera() { return scenario_->camera.camera; }

  // ATE after an SE3 alignment: the maps are metric, no scale correction.
  static eval::EvalResult se3Accuracy(const Trajectory& truth, const Trajectory& estimate) {
    eval::EvalOptions options;
    options.alignment = eval::Alignment::kSE3;
    return eval::evaluate(truth, estimate, options);
  }

  inline static std::unique_ptr<sim::Scenario> scenario_;
  inline static std::unique_ptr<std::vector<RenderedFrame>> frames_;
};

}  // namespace lvslam::visual::testing
