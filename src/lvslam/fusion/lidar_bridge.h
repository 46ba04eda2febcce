#pragma once
// The fusion framework's bridge to both subsystems (the only place where
// lidar/ and visual/ meet): LiDAR feature frames in as TimedFeatures, the
// paper's d_v_mean back out to the LiDAR's linear points, image line segments
// in as ImageSegments.
#include <span>
#include <vector>

#include "lvslam/fusion/feature_accumulator.h"
#include "lvslam/fusion/fusion_framework.h"
#include "lvslam/lidar/feature_point.h"
#include "lvslam/lidar/lidar_odometry.h"
#include "lvslam/visual/feature/line_extractor.h"

namespace lvslam::fusion {

// Planar classes (ground, facade, roof) carry their normal, linear ones
// (pillar, beam) their line direction; vertices are neither.
FeatureShape shapeOf(lidar::FeatureClass cls);

// The frame's features as the fusion framework takes them. The LiDAR
// subsystem has deskewed every point to the frame's time stamp, so each
// feature's time is that time stamp (its capture time is frame.timestamp +
// point.time, already compensated).
std::vector<TimedFeature> toTimedFeatures(const lidar::FeatureFrame& frame);

// The motion the accumulator places the frame with: the frame's pose at its
// time stamp (the only time its deskewed features carry).
ConstantVelocityMotion motionOf(const lidar::FeatureFrame& frame);

// Hands each update's d_v_mean to the LiDAR subsystem's linear points (before
// registration). Returns the number of points changed.
std::size_t applyDirectionUpdates(lidar::LidarOdometry& odometry, std::span<const LinearDirectionUpdate> updates);

// LSD segments in the pixels of the (distorted) image.
std::vector<ImageSegment> toImageSegments(const std::vector<visual::RawSegment>& segments);

}  // namespace lvslam::fusion
