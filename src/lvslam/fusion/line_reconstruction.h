#pragma once
// Reconstructs the 3D line behind one image segment from the LiDAR feature
// points next to its arc on the sphere (paper, "Depth and direction
// association"): plane-to-plane intersection when the neighbours are mostly
// planar, the dominant direction cluster L_best when they are mostly linear.
#include <optional>
#include <vector>

#include "lvslam/core/camera.h"
#include "lvslam/fusion/fusion_config.h"
#include "lvslam/fusion/fusion_line.h"
#include "lvslam/fusion/sphere_feature.h"
#include "lvslam/fusion/sphere_index.h"

namespace lvslam::fusion {

class LineReconstructor {
 public:
  LineReconstructor(const PinholeCamera& camera, const FusionConfig& config);

  // `features` are the aligned LiDAR features in the camera frame and `index`
  // the KD-tree over their bearings. Sets `why` when the line is rejected.
  std::optional<FusionLine> reconstruct(const ImageSegment& segment, const std::vector<SphereFeature>& features,
                                        const SphereIndex& index, RejectReason* why = nullptr) const;

 private:
  PinholeCamera camera_;
  FusionConfig config_;
};

}  // namespace lvslam::fusion
