#pragma once
// MULLS feature classes from ground segmentation and local PCA: ground,
// facade, roof, pillar, beam, vertex, each point with its primary direction.
#include <optional>
#include <vector>

#include "lvslam/lidar/deskew.h"
#include "lvslam/lidar/feature_point.h"
#include "lvslam/lidar/lidar_config.h"
#include "lvslam/lidar/pca.h"

namespace lvslam::lidar {

// The class of a non-ground point from its neighbourhood shape, or none
// (scattered, or a slanted line / plane). Sets `direction` for the class.
std::optional<FeatureClass> classifyShape(const LocalShape& shape, const FeatureConfig& config,
                                          Eigen::Vector3f& direction);

// Classified, per-class downsampled features of deskewed points (LiDAR frame).
std::vector<FeaturePoint> extractFeatures(const std::vector<TimedPoint>& points, const GroundConfig& ground,
                                          const FeatureConfig& config);

}  // namespace lvslam::lidar
