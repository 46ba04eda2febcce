#include "lvslam/visual/optimize/schur_system.h"

#include <algorithm>
#include <random>

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace lvslam::visual {
namespace {

// A random least-squares problem with the BA's structure: each residual
// block touches one pose and at most one landmark. Kept as a dense Jacobian
// too, so the Schur solution can be checked against a plain dense solve.
struct RandomProblem {
  static constexpr int kPoses = 3, kPoints = 5, kLines = 2;
  static constexpr int kUnknowns = 6 * kPoses + 3 * kPoints + 4 * kLines;
  Eigen::MatrixXd J;
  Eigen::VectorXd r;
  SchurSystem system{kPoses, kPoints, kLines};

  static int pointColumn(int j) { return 6 * kPoses + 3 * j; }
  static int lineColumn(int j) { return 6 * kPoses + 3 * kPoints + 4 * j; }

  explicit RandomProblem(unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> n(0.0, 1.0);
    std::vector<Eigen::MatrixXd> rows;
    std::vector<Eigen::VectorXd> residuals;
    const auto add = [&](int pose, int landmark_column, int landmark_size, auto landmark_block, int slot) {
      const int R = 2;
      Eigen::MatrixXd row = Eigen::MatrixXd::Zero(R, kUnknowns);
      Eigen::VectorXd e(R);
      for (int i = 0; i < R; ++i) e[i] = n(rng);
      Eigen::Matrix<double, 2, 6> J_pose;
      for (int i = 0; i < J_pose.size(); ++i) J_pose.data()[i] = n(rng);
      row.block(0, 6 * pose, R, 6) = J_pose;
      system.poseH(pose) += J_pose.transpose() * J_pose;
      system.poseG(pose) += J_pose.transpose() * e;
      if (landmark_block) {
        Eigen::MatrixXd J_l(R, landmark_size);
        for (int i = 0; i < J_l.size(); ++i) J_l.data()[i] = n(rng);
        row.block(0, landmark_column, R, landmark_size) = J_l;
        landmark_block->H += J_l.transpose() * J_l;
        landmark_block->g += J_l.transpose() * e;
        landmark_block->couplings[slot] += J_pose.transpose() * J_l;
      }
      rows.push_back(row);
      residuals.push_back(e);
    };
    for (int j = 0; j < kPoints; ++j) {
      for (int pose = 0; pose < kPoses; ++pose) {
        if ((j + pose) % 3 == 2) continue;  // not every pose sees every point
        const int slot = system.pointSlot(j, pose);
        add(pose, pointColumn(j), 3, &system.point(j), slot);
        add(pose, pointColumn(j), 3, &system.point(j), slot);  // a second term on the same pair (a depth)
      }
    }
    for (int j = 0; j < kLines; ++j) {
      for (int pose = 0; pose < kPoses; ++pose) {
        const int slot = system.lineSlot(j, pose);
        for (int k = 0; k < 2; ++k) add(pose, lineColumn(j), 4, &system.line(j), slot);
      }
    }
    add(0, 0, 0, static_cast<SchurLandmark<3>*>(nullptr), -1);  // a pose-only term (a prior)
    J.resize(static_cast<int>(rows.size()) * 2, kUnknowns);
    r.resize(J.rows());
    for (size_t i = 0; i < rows.size(); ++i) {
      J.middleRows(2 * static_cast<int>(i), 2) = rows[i];
      r.segment<2>(2 * static_cast<int>(i)) = residuals[i];
    }
  }

  Eigen::VectorXd flatten(const SchurSystem::Step& step) const {
    Eigen::VectorXd dx(kUnknowns);
    dx.head(6 * kPoses) = step.poses;
    for (int j = 0; j < kPoints; ++j) dx.segment<3>(pointColumn(j)) = step.points[j];
    for (int j = 0; j < kLines; ++j) dx.segment<4>(lineColumn(j)) = step.lines[j];
    return dx;
  }
};

TEST(SchurSystem, SolvesTheDampedNormalEquationsAsADenseSolveDoes) {
  for (unsigned seed : {1u, 2u, 3u}) {
    RandomProblem p(seed);
    const Eigen::MatrixXd H = p.J.transpose() * p.J;
    const Eigen::VectorXd g = p.J.transpose() * p.r;
    for (double mu : {1e-4, 1.0, 30.0}) {
      Eigen::MatrixXd damped = H;
      for (int i = 0; i < H.rows(); ++i) damped(i, i) += mu * std::clamp(H(i, i), 1e-6, 1e32);
      const Eigen::VectorXd expected = damped.ldlt().solve(-g);
      SchurSystem::Step step;
      ASSERT_TRUE(p.system.solve(mu, step));
      const Eigen::VectorXd dx = p.flatten(step);
      EXPECT_LT((dx - expected).norm(), 1e-9 * expected.norm()) << "seed " << seed << " mu " << mu;
      // The model decrease is that of the undamped quadratic, and equals the
      // cost drop of the linearised residuals r + J dx.
      const double model = -(g.dot(dx) + 0.5 * dx.dot(H * dx));
      EXPECT_NEAR(p.system.modelDecrease(step), model, 1e-9 * std::abs(model));
      EXPECT_NEAR(model, 0.5 * (p.r.squaredNorm() - (p.r + p.J * dx).squaredNorm()), 1e-9 * std::abs(model));
    }
    EXPECT_DOUBLE_EQ(p.system.maxGradient(), g.cwiseAbs().maxCoeff());
  }
}

// An unknown that no residual touches (all its observations were outliers)
// keeps a tiny damped diagonal: the solve goes through and leaves it still.
TEST(SchurSystem, AnUnknownNothingTouchesStaysStill) {
  RandomProblem p(4);
  p.system.point(2) = SchurLandmark<3>{};  // no terms, no couplings
  SchurSystem::Step step;
  ASSERT_TRUE(p.system.solve(1e-4, step));
  EXPECT_EQ(step.points[2], Eigen::Vector3d::Zero());
  EXPECT_TRUE(step.poses.allFinite());
  // setZero keeps the structure (slots) and clears every value.
  p.system.setZero();
  EXPECT_EQ(p.system.maxGradient(), 0.0);
  EXPECT_EQ(p.system.pointSlot(0, 1), 1);  // the existing slot, not a new one
}

}  // namespace
}  // namespace lvslam::visual
