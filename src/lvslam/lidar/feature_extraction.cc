#include "lvslam/lidar/feature_extraction.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

#include <tbb/parallel_for.h>

#include "lvslam/lidar/ground_segmentation.h"
#include "lvslam/lidar/point_kdtree.h"
#include "lvslam/lidar/preprocess.h"

namespace lvslam::lidar {

namespace {

// A real line crosses the rings: it needs this many rings, none holding more
// than this share of its points.
constexpr int kMinRingsOfLine = 3;
constexpr double kMaxRingShareOfLine = 0.4;

struct RingRange {
  int lowest = std::numeric_limits<int>::max();
  int highest = -1;
};

// The outermost rings end the view: a strip along them is an edge of the view.
bool crossesRings(std::span<int> rings, const RingRange& range) {
  if (rings.empty() || rings.front() < 0) return true;  // no ring data: trust the shape
  std::sort(rings.begin(), rings.end());
  if (rings.front() == range.lowest || rings.back() == range.highest) return false;
  std::size_t largest = 0;
  int distinct = 0;
  for (std::size_t i = 0, j = 0; i < rings.size(); i = j, ++distinct) {
    while (j < rings.size() && rings[j] == rings[i]) ++j;
    largest = std::max(largest, j - i);
  }
  return distinct >= kMinRingsOfLine &&
         static_cast<double>(largest) <= kMaxRingShareOfLine * static_cast<double>(rings.size());
}

struct Classified {
  bool valid = false;
  FeaturePoint point;
};

// PCA over the k nearest neighbours within the radius (MULLS's neighbourhood).
Classified classifyPoint(const std::vector<TimedPoint>& cloud, const PointKdTree<TimedPoint>& tree,
                         std::size_t index, const RingRange& ring_range, const FeatureConfig& config) {
  constexpr std::size_t kMaxNeighbours = 64;
  std::array<std::size_t, kMaxNeighbours> ids{};
  std::array<float, kMaxNeighbours> dist_sq{};
  const std::size_t found =
      knnWithinRadius(tree, cloud[index].p.data(), std::min(static_cast<std::size_t>(config.neighbours), kMaxNeighbours),
                      static_cast<float>(config.neighbour_radius), ids.data(), dist_sq.data());
  std::array<Eigen::Vector3f, kMaxNeighbours> neighbours;
  std::array<int, kMaxNeighbours> rings{};
  for (std::size_t j = 0; j < found; ++j) {
    neighbours[j] = cloud[ids[j]].p;
    rings[j] = cloud[ids[j]].ring;
  }
  Classified result;
  if (static_cast<int>(found) < config.min_neighbours) return result;
  const LocalShape shape = shapeOf(std::span<const Eigen::Vector3f>(neighbours.data(), found));
  if (!shape.valid) return result;
  Eigen::Vector3f direction;
  const auto cls = classifyShape(shape, config, direction);
  if (!cls) return result;
  // A strip of one or two scan lines on a wall or a far ceiling is "linear"
  // by its eigenvalues, but the line is the scan pattern's, not the scene's.
  if (isLinear(*cls) && !crossesRings(std::span<int>(rings.data(), found), ring_range)) return result;
  result.valid = true;
  result.point.p = cloud[index].p;
  result.point.time = cloud[index].time;
  result.point.cls = *cls;
  result.point.direction = direction;
  return result;
}

double voxelFor(FeatureClass cls, const FeatureConfig& config) {
  if (cls == FeatureClass::kGround) return config.ground_voxel;
  if (isPlanar(cls)) return config.planar_voxel;
  if (isLinear(cls)) return config.linear_voxel;
  return config.vertex_voxel;
}

std::vector<FeaturePoint> downsamplePerClass(const std::vector<FeaturePoint>& points, const FeatureConfig& config) {
  std::array<std::vector<FeaturePoint>, kFeatureClassCount> by_class;
  for (const FeaturePoint& point : points) by_class[static_cast<int>(point.cls)].push_back(point);
  std::vector<FeaturePoint> kept;
  for (int c = 0; c < kFeatureClassCount; ++c) {
    const double voxel = voxelFor(static_cast<FeatureClass>(c), config);
    const auto sampled = voxelDownsample(by_class[c], voxel, [](const FeaturePoint& fp) { return fp.p; });
    kept.insert(kept.end(), sampled.begin(), sampled.end());
  }
  return kept;
}

}  // namespace

std::optional<FeatureClass> classifyShape(const LocalShape& shape, const FeatureConfig& config,
                                          Eigen::Vector3f& direction) {
  if (shape.linearity > config.linearity_threshold) {
    direction = shape.line_direction;
    const float vertical = std::abs(direction.z());
    if (vertical > config.vertical_cos) return FeatureClass::kPillar;
    if (vertical < config.horizontal_cos) return FeatureClass::kBeam;
    return std::nullopt;
  }
  if (shape.planarity > config.planarity_threshold) {
    direction = shape.normal;
    const float vertical = std::abs(direction.z());
    if (vertical < config.horizontal_cos) return FeatureClass::kFacade;
    if (vertical > config.vertical_cos) return FeatureClass::kRoof;
    return std::nullopt;
  }
  if (shape.curvature > config.curvature_threshold) {
    direction = shape.normal;
    return FeatureClass::kVertex;
  }
  return std::nullopt;
}

std::vector<FeaturePoint> extractFeatures(const std::vector<TimedPoint>& points, const GroundConfig& ground,
                                          const FeatureConfig& config) {
  const GroundSegmentation segmentation = segmentGround(points, ground);
  std::vector<FeaturePoint> features;
  std::vector<std::size_t> off_ground;
  RingRange rings;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (points[i].ring >= 0) {
      rings.lowest = std::min(rings.lowest, points[i].ring);
      rings.highest = std::max(rings.highest, points[i].ring);
    }
    if (!segmentation.is_ground[i]) {
      off_ground.push_back(i);
      continue;
    }
    FeaturePoint fp;
    fp.p = points[i].p;
    fp.time = points[i].time;
    fp.cls = FeatureClass::kGround;
    fp.direction = segmentation.normal[i];
    features.push_back(fp);
  }
  if (points.size() >= static_cast<std::size_t>(config.min_neighbours)) {
    // Neighbourhoods include the ground, so that the foot of a wall is not a
    // "line" left over once the floor is taken away.
    const PointCloudAdaptor<TimedPoint> adaptor{points};
    PointKdTree<TimedPoint> tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16));
    tree.buildIndex();
    // Per-class downsampling keeps one point per voxel anyway: PCA only on one
    // candidate per (smaller) voxel, the dominant cost on dense outdoor scans.
    const std::vector<std::size_t> candidates =
        config.candidate_voxel > 0.0
            ? voxelDownsample(off_ground, config.candidate_voxel, [&](std::size_t i) { return points[i].p; })
            : off_ground;
    std::vector<Classified> classified(candidates.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, candidates.size(), 256),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for (std::size_t i = range.begin(); i != range.end(); ++i)
                          classified[i] = classifyPoint(points, tree, candidates[i], rings, config);
                      });
    for (const Classified& c : classified)
      if (c.valid) features.push_back(c.point);
  }
  return downsamplePerClass(features, config);
}

}  // namespace lvslam::lidar
