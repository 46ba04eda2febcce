#pragma once
// The normal equations of a bundle adjustment in which every residual touches
// at most one pose and one landmark, and their damped solution by eliminating
// every landmark (Schur complement; Triggs et al. 2000, "Bundle Adjustment -
// A Modern Synthesis", Sec. 6.1). This is what Ceres' SPARSE_SCHUR does,
// without its per-residual-block bookkeeping, which cost more than the
// algebra in local BA (docs/history/2026-11-fusion-sessions.md, "Local BA
// without Ceres").
//
// Poses have 6 unknowns, points 3 and lines 4. The pose-pose part is block
// diagonal (no residual touches two poses), so the reduced system is
// assembled densely over the free poses of the window.
#include <vector>

#include <Eigen/Core>

namespace lvslam::visual {

template <int D>
struct SchurLandmark {
  using Matrix = Eigen::Matrix<double, D, D>;
  using Vector = Eigen::Matrix<double, D, 1>;
  using Coupling = Eigen::Matrix<double, 6, D>;

  Matrix H = Matrix::Zero();
  Vector g = Vector::Zero();
  std::vector<int> poses;           // free pose index of each coupling block
  std::vector<Coupling> couplings;  // H(pose, landmark)
};

class SchurSystem {
 public:
  using Matrix6 = Eigen::Matrix<double, 6, 6>;
  using Vector6 = Eigen::Matrix<double, 6, 1>;

  struct Step {
    Eigen::VectorXd poses;  // 6 per free pose
    std::vector<Eigen::Vector3d> points;
    std::vector<Eigen::Vector4d> lines;
  };

  SchurSystem(int free_poses, int points, int lines);

  // The coupling block of (landmark, free pose), created on first use; call
  // while building the structure, then address blocks by the slot returned.
  int pointSlot(int point, int pose);
  int lineSlot(int line, int pose);

  void setZero();  // keeps the structure

  Matrix6& poseH(int pose) { return pose_H_[pose]; }
  Vector6& poseG(int pose) { return pose_g_[pose]; }
  SchurLandmark<3>& point(int point) { return points_[point]; }
  SchurLandmark<4>& line(int line) { return lines_[line]; }

  // Solves (H + mu D) step = -g with D the diagonal of H clamped to
  // [1e-6, 1e32] (Levenberg-Marquardt as Ceres damps it). False when a
  // damped block or the reduced system is not positive definite.
  bool solve(double mu, Step& step) const;

  // -(g' step + step' H step / 2): the decrease the undamped quadratic model
  // predicts for the step.
  double modelDecrease(const Step& step) const;

  double maxGradient() const;  // largest |g|: a zero gradient is converged

 private:
  template <int D>
  static int slotOf(SchurLandmark<D>& landmark, int pose);

  std::vector<Matrix6> pose_H_;  // one per free pose
  std::vector<Vector6> pose_g_;
  std::vector<SchurLandmark<3>> points_;
  std::vector<SchurLandmark<4>> lines_;
};

}  // namespace lvslam::visual
