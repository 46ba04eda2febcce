#pragma once
// What `lvslam eval` compares an estimate with: a ground truth and, when
// known, its sensor frame and the rig's T_camera_lidar, from a sequence
// folder or from plain files.
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "lvslam/core/trajectory.h"
#include "lvslam/io/sequence_info.h"

namespace lvslam {

struct GroundTruthReference {
  Trajectory trajectory;
  std::string path;                              // of the ground-truth file, for messages
  std::optional<GroundTruthFrame> frame;         // none: nobody said
  std::optional<Eigen::Isometry3d> T_camera_lidar;
  // The frame `lvslam run` writes its trajectory in for this sequence (the
  // camera's when it has one); none for plain files.
  std::optional<GroundTruthFrame> run_output_frame;
};

// groundtruth.txt, groundtruth.frame and the extrinsics of a sequence folder;
// throws lvslam::Error naming the file or key that is missing or malformed.
GroundTruthReference groundTruthOfSequence(const std::string& sequence_dir);

// T_camera_lidar from a sequence.yaml (extrinsics.T_camera_lidar) or from a
// YAML file whose top level has T_camera_lidar (row-major 4x4).
Eigen::Isometry3d readExtrinsicFile(const std::string& path);

}  // namespace lvslam
