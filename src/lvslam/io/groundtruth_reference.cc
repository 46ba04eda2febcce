#include "lvslam/io/groundtruth_reference.h"

#include <filesystem>

#include "lvslam/core/error.h"
#include "lvslam/core/file_access.h"
#include "lvslam/core/yaml_config.h"
#include "lvslam/io/tum.h"

namespace lvslam {

GroundTruthReference groundTruthOfSequence(const std::string& sequence_dir) {
  const std::filesystem::path dir(sequence_dir);
  if (fileKind(sequence_dir) != FileKind::kDirectory) throw Error(sequence_dir, "sequence folder not found");
  const std::string yaml = (dir / "sequence.yaml").string();
  const SequenceInfo info = readSequenceInfo(yaml);
  GroundTruthReference ref;
  ref.path = (dir / "groundtruth.txt").string();
  if (fileKind(ref.path) != FileKind::kRegular) throw Error(ref.path, "file not found: the sequence has no ground truth");
  if (!info.groundtruth_frame)
    throw Error(yaml, "key 'groundtruth.frame': missing required key (groundtruth.txt exists)");
  ref.trajectory = readTum(ref.path);
  ref.frame = info.groundtruth_frame;
  if (info.camera && info.lidar) ref.T_camera_lidar = info.T_camera_lidar;
  ref.run_output_frame = info.camera ? GroundTruthFrame::kCamera : GroundTruthFrame::kLidar;
  return ref;
}

Eigen::Isometry3d readExtrinsicFile(const std::string& path) {
  const YamlConfig root = YamlConfig::loadFile(path);
  if (const auto ext = root.find("extrinsics")) return parseTransformMatrix(ext->at("T_camera_lidar"));
  return parseTransformMatrix(root.at("T_camera_lidar"));
}

}  // namespace lvslam
