#pragma once
// Scan Context, the LiDAR place descriptor of Kim & Kim (IROS 2018): a polar
// grid around the sensor (rings by range, sectors by azimuth) holding the
// highest point of each bin; a rotation-invariant ring key finds candidates,
// then the column-shift-invariant cosine distance compares the grids and
// its best shift gives the yaw between the two scans.
#include <vector>

#include <Eigen/Core>

#include "lvslam/lidar/feature_point.h"

namespace lvslam::loop {

struct ScanContextConfig {
  int rings = 20;
  int sectors = 60;
  double max_radius = 30.0;   // metres; farther points are left out
  // Added to a point's z (LiDAR frame) so that every bin holding a point is
  // positive: the LiDAR's height above the lowest surface it sees, and more.
  double height_offset = 2.0;
};

struct ScanContext {
  Eigen::MatrixXf bins;     // rings x sectors: highest z + height_offset, 0 where empty
  Eigen::VectorXf ring_key; // per ring, the mean of its bins (rotation invariant)
};

ScanContext makeScanContext(const std::vector<Eigen::Vector3f>& points_lidar, const ScanContextConfig& config);
// The same of a keyframe's feature points (their positions).
ScanContext scanContextOf(const std::vector<lidar::FeaturePoint>& points_lidar, const ScanContextConfig& config);

struct ScanContextMatch {
  double distance = 1.0;  // in [0, 1]: mean over the columns both scans fill of 1 - cos
  int shift = 0;          // query sector j matches candidate sector j + shift
  // Yaw of the query's LiDAR in the candidate's (rotation about z of
  // T_candidate_query), from the shift.
  double yaw = 0.0;
};

// Best over all column shifts; distance 1 when no column is filled in both.
ScanContextMatch compareScanContexts(const ScanContext& query, const ScanContext& candidate);

double ringKeyDistance(const ScanContext& a, const ScanContext& b);

}  // namespace lvslam::loop
