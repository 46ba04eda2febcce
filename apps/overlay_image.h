#pragma once
// The picture of `lvslam overlay`, with which a user checks an extrinsic
// calibration: LiDAR feature points (coloured by shape, shaded by depth),
// image line segments, and the fusion lines drawn over the camera frame.
#include <vector>

#include <opencv2/core.hpp>

#include "lvslam/core/camera.h"
#include "lvslam/fusion/fusion_line.h"
#include "lvslam/fusion/sphere_feature.h"

namespace lvslam::apps {

// Planar points green, linear red, others blue, darker when farther;
// segments thin yellow; fusion lines thick magenta from their 3D endpoints.
cv::Mat drawOverlayImage(const cv::Mat& image, const PinholeCamera& camera,
                         const std::vector<fusion::SphereFeature>& features,
                         const std::vector<fusion::ImageSegment>& segments, const std::vector<fusion::FusionLine>& lines);

}  // namespace lvslam::apps
