#pragma once
// Do LiDAR edges and image edges still line up? A wrong LiDAR-camera
// extrinsic rotation turns every projected LiDAR feature by the same
// rotation on the camera's sphere, so the fusion framework's associations
// (LiDAR line features next to an image segment's great circle) show it as
// one rotation common to the whole run. Per window of frames the check fits
// that rotation (Gauss-Newton, association gate shrinking from twice the
// fusion's own to half of it); over the windows so far it tests whether their
// mean exceeds a tolerance, against the windows' own scatter (one-sided
// Student t at 99.9 % along the mean's direction). The scatter between
// windows, not the residuals within one, is the yardstick: on the simulated
// scenes a window's associations are consistent with themselves yet its
// rotation differs from the next window's by degrees (a LiDAR edge meets the
// parallel image line of a baseboard or a frame as readily as its own).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lvslam/core/camera.h"
#include "lvslam/fusion/fusion_config.h"
#include "lvslam/fusion/fusion_line.h"
#include "lvslam/fusion/sphere_feature.h"

namespace lvslam::fusion {

// After each window: that window's fit and the test over all windows so far.
// Rotations (camera frame) carry the projected LiDAR features onto the image
// edges: the extrinsic's rotation error, inverted.
struct ExtrinsicVerdict {
  double t_first = 0.0, t_last = 0.0;  // camera times of the window's first and last frame
  int frames = 0;                       // of this window
  std::size_t associations = 0;         // of this window
  Eigen::Vector3d window_rotation = Eigen::Vector3d::Zero();
  int windows = 0;                      // in the test (the last kMaxWindows)
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();  // mean over the windows
  double misalignment_deg = 0.0;        // |rotation|
  double sigma_deg = 0.0;               // standard error of the mean along its direction (inf: too few windows)
  bool misaligned = false;              // exceeds the tolerance at 99.9 %
};

class ExtrinsicCheck {
 public:
  // Windows of this many blocks of accumulated_scans scans (2 s at 10 Hz).
  static constexpr int kBlocksPerWindow = 4;
  static constexpr int kMinWindows = 4;  // fewer say nothing about their scatter
  // The test looks at the last 30 s only: the scenes' own offset between
  // LiDAR line features and image edges (degrees; docs/benchmarks.md, "The
  // extrinsic check") does not shrink with the run's length, the standard
  // error of a growing window would, until a correct calibration failed the
  // test.
  static constexpr int kMaxWindows = 15;
  // A misalignment below this is within what a careful calibration achieves
  // and well inside the fusion's 3 deg association gate: no warning.
  static constexpr double kToleranceDeg = 1.0;

  ExtrinsicCheck(const PinholeCamera& camera, const FusionConfig& config);

  // One camera frame: the accumulated LiDAR features in its camera frame (as
  // FusionFramework::featuresInCamera gives them) and its image segments.
  // `scan_serial` counts the LiDAR scans so far (a frame before the
  // accumulation is full is skipped). Returns a verdict when the frame
  // closes a window.
  std::optional<ExtrinsicVerdict> addFrame(std::size_t scan_serial, double t_camera,
                                           const std::vector<SphereFeature>& features,
                                           const std::vector<ImageSegment>& segments);

  // Closes the last window at the end of the run when it spans all its
  // blocks; none otherwise.
  std::optional<ExtrinsicVerdict> finish();

  // Each image segment's great circle: the unit rays of its ends and the
  // plane's unit normal.
  struct Arc {
    Eigen::Vector3d a, b, n;
  };
  // A LiDAR line feature on the sphere: unit bearing and unit direction.
  struct Edge {
    Eigen::Vector3d bearing, direction;
  };
  struct Frame {
    double t = 0.0;
    std::vector<Edge> edges;
    std::vector<Arc> arcs;
  };
  // The rotation of one window's frames (exposed for tests); none when
  // the associations leave a direction unconstrained.
  std::optional<Eigen::Vector3d> fitRotation(const std::vector<Frame>& frames, std::size_t* associations = nullptr) const;

 private:
  ExtrinsicVerdict closeWindow();

  PinholeCamera camera_;
  FusionConfig config_;
  std::vector<Frame> window_;
  std::size_t window_block_ = 0, last_block_ = 0;  // the window's first block, the last frame's
  std::vector<Eigen::Vector3d> window_rotations_;
};

// One-sided Student t quantile at 99.9 % for `dof` degrees of freedom.
double studentT999(int dof);

// The warning line a misaligned verdict would give (not printed yet: the
// simulated scenes' own offsets are as large as the errors to be found,
// docs/benchmarks.md, "The extrinsic check"). Names where the extrinsic was
// read (`where`, e.g. "seq/sequence.yaml: key 'extrinsics.T_camera_lidar'")
// and the estimate.
std::string extrinsicWarning(const ExtrinsicVerdict& verdict, const std::string& where);

}  // namespace lvslam::fusion
