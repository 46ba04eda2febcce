#pragma once
// Writes a whole simulated sequence folder (docs/sequence-format.md, details
// in docs/simulator.md), streaming: one image or scan in memory at a time.
#include <functional>
#include <string>

#include <Eigen/Geometry>

#include "lvslam/sim/scenario.h"

namespace lvslam::sim {

struct SimulationSummary {
  int images = 0;
  int scans = 0;
  int groundtruth_poses = 0;
};

// Throws lvslam::Error naming the option on invalid options, or the file
// that cannot be written.
SimulationSummary simulateSequence(const SimOptions& options, const std::string& out_dir);

// The sequence in out_dir, simulated only when out_dir has no
// sequence.yaml: written into "<out_dir>.partial" and renamed when complete
// (io/atomic_folder.h), so an interrupted run never leaves a half sequence
// that looks whole (a leftover partial is replaced; an out_dir without
// sequence.yaml is replaced only when empty). `announce` is
// called just before a simulation starts. Returns whether it simulated.
bool simulateSequenceOnce(const SimOptions& options, const std::string& out_dir,
                          const std::function<void()>& announce = {});

// T_camera_lidar with the requested error: R' = R_err R, t' = t + t_err, the
// rotation error `rotation_deg` about an axis and the offset
// `translation_m` in a direction both drawn from the seed.
Eigen::Isometry3d perturbExtrinsics(const Eigen::Isometry3d& T_camera_lidar, const ExtrinsicError& error,
                                    std::uint64_t seed);

// groundtruth.txt: poses on this grid and at every image and scan time.
inline constexpr double kGroundTruthRateHz = 200.0;
inline constexpr const char* kExtrinsicsTruthFile = "extrinsics_truth.yaml";

}  // namespace lvslam::sim
