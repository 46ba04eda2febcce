// The offline refinement's chunked smoothing against the whole graph solved at once.
#include "lvslam/system/offline/chunked_smoothing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "lvslam/core/error.h"
#include "lvslam/system/online/pose_information.h"
#include "support/record_files.h"

namespace lvslam::system {
namespace {

Eigen::Isometry3d truePose(int i) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = expSO3(Eigen::Vector3d(0.0, 0.0, 0.01 * i));
  T.translation() = Eigen::Vector3d(0.1 * i, std::sin(0.05 * i), 0.0);
  return T;
}

// A drive of `count` poses: precise odometry between consecutive ones (2 mm,
// 0.05 deg) and, per pose, a coarse measurement in the world (2 cm, 0.5
// deg; what a consistent map gives each frame), both with noise; every node
// started from the dead-reckoned odometry, the first held. The poses a
// measurement moves are those within the ratio of the two sigmas, about 10
// poses: much less than a chunk, as in the estimator's graph.
struct Drive {
  std::vector<PoseNode> nodes;
  std::vector<PoseFactor> factors;
};

Eigen::Isometry3d perturbed(const Eigen::Isometry3d& T, double sigma_m, double sigma_rad, std::mt19937& rng) {
  std::normal_distribution<double> noise(0.0, 1.0);
  Eigen::Isometry3d error = Eigen::Isometry3d::Identity();
  error.linear() = expSO3(sigma_rad * Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
  error.translation() = sigma_m * Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
  return T * error;
}

Drive makeDrive(int count) {
  std::mt19937 rng(7);
  const double odometry_m = 0.002, odometry_rad = 0.05 * M_PI / 180.0;
  const double world_m = 0.02, world_rad = 0.5 * M_PI / 180.0;
  Drive drive;
  drive.nodes.push_back({truePose(0), true});
  for (int i = 1; i < count; ++i) {
    const Eigen::Isometry3d step = perturbed(truePose(i - 1).inverse() * truePose(i), odometry_m, odometry_rad, rng);
    drive.factors.push_back(
        {i - 1, i, step, isotropicCovariance(odometry_m, odometry_rad).inverse(), FactorSource::kLidar});
    drive.factors.push_back({0, i, perturbed(truePose(i), world_m, world_rad, rng),
                             isotropicCovariance(world_m, world_rad).inverse(), FactorSource::kVisual});
    drive.nodes.push_back({drive.nodes.back().T_world_camera * step, false});
  }
  return drive;
}

double rmsError(const std::vector<PoseNode>& nodes) {
  double sum = 0.0;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    sum += (nodes[i].T_world_camera.translation() - truePose(static_cast<int>(i)).translation()).squaredNorm();
  return std::sqrt(sum / static_cast<double>(nodes.size()));
}

ChunkedSmoothingConfig smallChunks(int sweeps) {
  ChunkedSmoothingConfig config;
  config.chunk_nodes = 60;
  config.overlap_nodes = 20;
  config.sweeps = sweeps;
  config.solve.huber_delta = 1e6;  // quadratic: the whole graph's solution is the least-squares one
  return config;
}

// 400 poses in chunks of 60 overlapping by 20: the chunked solution is the
// whole graph's to a small fraction of the correction it makes.
TEST(ChunkedSmoothing, ALongDriveSmoothedInChunksIsTheWholeGraphsSolution) {
  const Drive drive = makeDrive(400);
  std::vector<PoseNode> whole = drive.nodes;
  const ChunkedSmoothingConfig config = smallChunks(2);
  ASSERT_TRUE(solvePoseGraph(whole, drive.factors, config.solve));
  double correction = 0.0, difference = 0.0;
  std::vector<PoseNode> chunked = drive.nodes;
  smoothInChunks(chunked, testing::recordFileOf(drive.factors), config);
  for (std::size_t i = 0; i < whole.size(); ++i) {
    const Eigen::Vector3d t = whole[i].T_world_camera.translation();
    correction = std::max(correction, (t - drive.nodes[i].T_world_camera.translation()).norm());
    difference = std::max(difference, (t - chunked[i].T_world_camera.translation()).norm());
  }
  ASSERT_GT(correction, 0.05);  // the dead-reckoned drive is centimetres off
  EXPECT_LT(difference, 0.02 * correction);
  EXPECT_LT(rmsError(chunked), 1.05 * rmsError(whole));
  EXPECT_LT(rmsError(whole), 0.5 * rmsError(drive.nodes));
}

// A graph no larger than one chunk is solved whole, exactly as solvePoseGraph does.
TEST(ChunkedSmoothing, AGraphWithinOneChunkIsSolvedWhole) {
  const Drive drive = makeDrive(50);
  std::vector<PoseNode> whole = drive.nodes, chunked = drive.nodes;
  const ChunkedSmoothingConfig config = smallChunks(2);
  ASSERT_TRUE(solvePoseGraph(whole, drive.factors, config.solve));
  smoothInChunks(chunked, testing::recordFileOf(drive.factors), config);
  for (std::size_t i = 0; i < whole.size(); ++i)
    EXPECT_TRUE(whole[i].T_world_camera.matrix() == chunked[i].T_world_camera.matrix()) << i;
}

TEST(ChunkedSmoothing, ChunksMustBeLargerThanTheirOverlap) {
  Drive drive = makeDrive(10);
  ChunkedSmoothingConfig config = smallChunks(2);
  config.overlap_nodes = config.chunk_nodes;
  EXPECT_THROW(smoothInChunks(drive.nodes, testing::recordFileOf(drive.factors), config), Error);
  config = smallChunks(0);
  EXPECT_THROW(smoothInChunks(drive.nodes, testing::recordFileOf(drive.factors), config), Error);
}

}  // namespace
}  // namespace lvslam::system
