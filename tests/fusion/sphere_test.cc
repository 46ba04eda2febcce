#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "lvslam/fusion/sphere_geometry.h"
#include "lvslam/fusion/sphere_index.h"

namespace lvslam::fusion {
namespace {

constexpr double kDeg = M_PI / 180.0;

TEST(SphereGeometry, ArcSamplesAreUniformStepsOnTheGreatCircle) {
  const Eigen::Vector3d a = Eigen::Vector3d(-0.3, 0.1, 1.0).normalized();
  const Eigen::Vector3d b = Eigen::Vector3d(0.4, -0.2, 1.0).normalized();
  const double step = 0.2 * kDeg;
  const auto samples = sampleArc(a, b, step);
  const double theta = angleBetween(a, b);
  ASSERT_EQ(samples.size(), static_cast<std::size_t>(std::floor(theta / step)) + 2);
  EXPECT_LT((samples.front() - a).norm(), 1e-15);
  EXPECT_LT((samples.back() - b).norm(), 1e-15);
  const Eigen::Vector3d normal = a.cross(b).normalized();
  for (std::size_t i = 0; i < samples.size(); ++i) {
    EXPECT_NEAR(samples[i].norm(), 1.0, 1e-12);
    EXPECT_NEAR(samples[i].dot(normal), 0.0, 1e-12);  // on the great circle of a and b
    EXPECT_NEAR(angleBetween(a, samples[i]), std::min(i * step, theta), 1e-12);
  }
  EXPECT_LE(angleBetween(samples[samples.size() - 2], b), step + 1e-12);
}

TEST(SphereGeometry, DegenerateArcIsOneSample) {
  const Eigen::Vector3d a = Eigen::Vector3d::UnitZ();
  EXPECT_EQ(sampleArc(a, a, 0.01).size(), 1u);
}

TEST(SphereGeometry, ChordAndAngleAgree) {
  for (double angle : {1e-6, 0.01, 0.5, 2.0, M_PI}) {
    const Eigen::Vector3d a = Eigen::Vector3d::UnitX();
    const Eigen::Vector3d b(std::cos(angle), std::sin(angle), 0.0);
    EXPECT_NEAR(chordToAngle((a - b).norm()), angle, 1e-9);
    EXPECT_NEAR(angleBetween(a, b), angle, 1e-12);
  }
}

TEST(SphereIndex, NearestMatchesBruteForce) {
  std::mt19937 rng(7);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<SphereFeature> features(2000);
  for (auto& f : features) f.p_camera = Eigen::Vector3d(g(rng), g(rng), g(rng)) * (1.0 + std::abs(g(rng)) * 10.0);
  const SphereIndex index(features);
  for (int q = 0; q < 200; ++q) {
    const Eigen::Vector3d query = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    std::size_t best = 0;
    double best_angle = 10.0;
    for (std::size_t i = 0; i < features.size(); ++i) {
      const double ang = angleBetween(query, features[i].p_camera.normalized());
      if (ang < best_angle) best_angle = ang, best = i;
    }
    SphereNeighbour nb;
    ASSERT_TRUE(index.nearest(query, nb));
    EXPECT_EQ(nb.index, best);
    EXPECT_NEAR(nb.angle, best_angle, 1e-9);
  }
}

TEST(SphereIndex, EmptyIndexFindsNothing) {
  const SphereIndex index({});
  SphereNeighbour nb;
  EXPECT_FALSE(index.nearest(Eigen::Vector3d::UnitZ(), nb));
}

}  // namespace
}  // namespace lvslam::fusion
