#pragma once
// The visual subsystem's fast motion in the fused output. The output rests on
// the LiDAR odometry; where vision is trusted its error is, band by band,
// independent of the LiDAR's, and below it in some bands (the LiDAR's
// vertical error at 0.5-2 Hz on the gate, 7.7 mm against vision's 4.9:
// docs/benchmarks.md, "Where the error lives"), above it in others (vision's
// frame-to-frame noise above 4 Hz, 2-3x the LiDAR's in the hall). So the
// output takes a share of the band-passed difference d = c_visual - c_output
// of the camera centres: d smoothed by a narrow Gaussian minus d smoothed by
// a wide one, over each run of trusted frames of one visual map. The output
// is assembled after the run, so both Gaussians are centred (zero phase: no
// lag at the platform's 1.7-5.3 Hz shake); a slow offset between the two,
// which the drift-aware fusion already weighs, passes unchanged.
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace lvslam::system {

struct VisualBandPassConfig {
  // Share of the band-passed difference (0: off) across the odometry
  // frame's x and y (horizontal for a level LiDAR) and along its z: the
  // platform's shake (roll, pitch, height) is vertical, which 10 Hz sweeps
  // follow worst and vision best. 0.4 and 0.8 of 0.3-0.5 and 0.5-1.0 on the
  // nine bench sequences (docs/benchmarks.md, "Decoupled visual information").
  double gain = 0.4;
  double gain_vertical = 0.8;
  double sigma_s = 0.32;  // the wide Gaussian: a cut near 0.5 Hz
  // The narrow one: the band's top (response 1/2 near 4.7 Hz; 0 keeps every
  // frame's own difference, a high-pass). 0.04 of 0.03-0.05 on the nine
  // bench sequences (docs/benchmarks.md, "A zero-phase band-pass").
  double sigma_fast_s = 0.04;
};

// One camera frame's difference d, absent while vision is not trusted.
struct VisualDifference {
  double t = 0.0;
  int map_id = -1;
  std::optional<Eigen::Vector3d> d;
};

// The correction of each frame's output camera centre, in the order given
// (times ascending): zero where d is absent; each run of frames with d and
// one map id is filtered on its own, a Gaussian's weights renormalised
// where it meets the run's ends.
std::vector<Eigen::Vector3d> visualBandPass(const std::vector<VisualDifference>& frames,
                                            const VisualBandPassConfig& config);

}  // namespace lvslam::system
