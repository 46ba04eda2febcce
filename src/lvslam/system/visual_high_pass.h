#pragma once
// The visual subsystem's fast motion in the fused output. The output rests on
// the LiDAR odometry; where vision is trusted its error is, band by band,
// independent of the LiDAR's, and below it in some bands (the LiDAR's
// vertical error at 0.5-2 Hz on the gate, 7.7 mm against vision's 4.9:
// docs/benchmarks.md, "Where the error lives"). So the output takes a share
// of the high-passed difference d = c_visual - c_output of the camera
// centres: d minus its Gaussian-weighted mean over the last three sigma
// seconds of trusted frames of the same visual map. Only past frames count,
// and a slow offset between the two, which the drift-aware fusion already
// weighs, passes unchanged.
#include <deque>
#include <optional>

#include <Eigen/Core>

namespace lvslam::system {

struct VisualHighPassConfig {
  // Share of the high-passed difference (0: off) across the odometry
  // frame's x and y (horizontal for a level LiDAR) and along its z: the
  // platform's shake (roll, pitch, height) is vertical, which 10 Hz sweeps
  // follow worst and vision best. 0.4 and 0.8 of 0.3-0.5 and 0.5-1.0 on the
  // nine bench sequences (docs/benchmarks.md, "Decoupled visual information").
  double gain = 0.4;
  double gain_vertical = 0.8;
  double sigma_s = 0.32;  // width of the mean: a cut near 0.5 Hz
};

class VisualHighPass {
 public:
  explicit VisualHighPass(const VisualHighPassConfig& config) : config_(config) {}

  // The correction of the output's camera centre at time t: none while
  // vision is not trusted (`difference` empty), which also starts the mean
  // anew, as does a change of visual map.
  Eigen::Vector3d add(double t, int map_id, const std::optional<Eigen::Vector3d>& difference);

 private:
  struct Sample {
    double t;
    Eigen::Vector3d d;
  };
  VisualHighPassConfig config_;
  std::deque<Sample> window_;
  int map_id_ = -1;
};

}  // namespace lvslam::system
