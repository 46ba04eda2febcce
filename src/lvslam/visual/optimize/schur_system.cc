#include "lvslam/visual/optimize/schur_system.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

namespace lvslam::visual {

namespace {

// Ceres' min_lm_diagonal / max_lm_diagonal: an unknown no residual moves
// still gets a little damping, so every block stays invertible.
constexpr double kMinDiagonal = 1e-6;
constexpr double kMaxDiagonal = 1e32;

template <int D>
Eigen::Matrix<double, D, D> damped(const Eigen::Matrix<double, D, D>& H, double mu) {
  Eigen::Matrix<double, D, D> out = H;
  for (int i = 0; i < D; ++i) out(i, i) += mu * std::clamp(H(i, i), kMinDiagonal, kMaxDiagonal);
  return out;
}

// One group of landmarks out of the system: S -= W H^-1 W', b += W H^-1 g
// (upper blocks of S only), keeping each H^-1 for the back-substitution.
template <int D>
bool eliminate(const std::vector<SchurLandmark<D>>& landmarks, double mu, Eigen::MatrixXd& S,
               Eigen::VectorXd& b, std::vector<Eigen::Matrix<double, D, D>>& inverses) {
  using Matrix = Eigen::Matrix<double, D, D>;
  inverses.resize(landmarks.size());
  std::vector<Eigen::Matrix<double, 6, D>> V;
  for (size_t j = 0; j < landmarks.size(); ++j) {
    const SchurLandmark<D>& l = landmarks[j];
    const Eigen::LLT<Matrix> llt(damped<D>(l.H, mu));
    if (llt.info() != Eigen::Success) return false;
    inverses[j] = llt.solve(Matrix::Identity());
    V.resize(l.poses.size());
    for (size_t s = 0; s < l.poses.size(); ++s) {
      V[s] = l.couplings[s] * inverses[j];
      b.segment<6>(6 * l.poses[s]) += V[s] * l.g;
    }
    for (size_t s = 0; s < l.poses.size(); ++s) {
      for (size_t t = 0; t < l.poses.size(); ++t) {
        if (l.poses[s] > l.poses[t]) continue;
        S.block<6, 6>(6 * l.poses[s], 6 * l.poses[t]).noalias() -= V[s] * l.couplings[t].transpose();
      }
    }
  }
  return true;
}

template <int D>
void backSubstitute(const std::vector<SchurLandmark<D>>& landmarks,
                    const std::vector<Eigen::Matrix<double, D, D>>& inverses, const Eigen::VectorXd& dx_poses,
                    std::vector<Eigen::Matrix<double, D, 1>>& dx) {
  dx.resize(landmarks.size());
  for (size_t j = 0; j < landmarks.size(); ++j) {
    const SchurLandmark<D>& l = landmarks[j];
    Eigen::Matrix<double, D, 1> rhs = -l.g;
    for (size_t s = 0; s < l.poses.size(); ++s)
      rhs.noalias() -= l.couplings[s].transpose() * dx_poses.segment<6>(6 * l.poses[s]);
    dx[j] = inverses[j] * rhs;
  }
}

// g' dx + dx' H dx / 2 of one landmark group, its coupling terms included.
template <int D>
double landmarkModel(const std::vector<SchurLandmark<D>>& landmarks, const Eigen::VectorXd& dx_poses,
                     const std::vector<Eigen::Matrix<double, D, 1>>& dx) {
  double sum = 0.0;
  for (size_t j = 0; j < landmarks.size(); ++j) {
    const SchurLandmark<D>& l = landmarks[j];
    sum += l.g.dot(dx[j]) + 0.5 * dx[j].dot(l.H * dx[j]);
    for (size_t s = 0; s < l.poses.size(); ++s)
      sum += dx_poses.segment<6>(6 * l.poses[s]).dot(l.couplings[s] * dx[j]);
  }
  return sum;
}

template <int D>
double maxLandmarkGradient(const std::vector<SchurLandmark<D>>& landmarks) {
  double m = 0.0;
  for (const SchurLandmark<D>& l : landmarks) m = std::max(m, l.g.cwiseAbs().maxCoeff());
  return m;
}

}  // namespace

SchurSystem::SchurSystem(int free_poses, int points, int lines)
    : pose_H_(free_poses), pose_g_(free_poses), points_(points), lines_(lines) {
  setZero();
}

template <int D>
int SchurSystem::slotOf(SchurLandmark<D>& landmark, int pose) {
  const auto it = std::find(landmark.poses.begin(), landmark.poses.end(), pose);
  if (it != landmark.poses.end()) return static_cast<int>(it - landmark.poses.begin());
  using Coupling = typename SchurLandmark<D>::Coupling;
  landmark.poses.push_back(pose);
  landmark.couplings.push_back(Coupling::Zero());
  return static_cast<int>(landmark.poses.size()) - 1;
}

int SchurSystem::pointSlot(int point, int pose) { return slotOf(points_[point], pose); }
int SchurSystem::lineSlot(int line, int pose) { return slotOf(lines_[line], pose); }

void SchurSystem::setZero() {
  for (Matrix6& H : pose_H_) H.setZero();
  for (Vector6& g : pose_g_) g.setZero();
  const auto clear = [](auto& landmarks) {
    for (auto& l : landmarks) {
      l.H.setZero();
      l.g.setZero();
      for (auto& W : l.couplings) W.setZero();
    }
  };
  clear(points_);
  clear(lines_);
}

bool SchurSystem::solve(double mu, Step& step) const {
  const int free_poses = static_cast<int>(pose_H_.size());
  const int n = 6 * free_poses;
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd b(n);
  for (int a = 0; a < free_poses; ++a) {
    S.block<6, 6>(6 * a, 6 * a) = damped<6>(pose_H_[a], mu);
    b.segment<6>(6 * a) = -pose_g_[a];
  }
  std::vector<Eigen::Matrix3d> point_inverses;
  std::vector<Eigen::Matrix4d> line_inverses;
  if (!eliminate(points_, mu, S, b, point_inverses) || !eliminate(lines_, mu, S, b, line_inverses)) return false;
  step.poses.resize(n);
  if (n > 0) {
    const Eigen::LLT<Eigen::MatrixXd, Eigen::Upper> llt(S);
    if (llt.info() != Eigen::Success) return false;
    step.poses = llt.solve(b);
    if (!step.poses.allFinite()) return false;
  }
  backSubstitute(points_, point_inverses, step.poses, step.points);
  backSubstitute(lines_, line_inverses, step.poses, step.lines);
  return true;
}

double SchurSystem::modelDecrease(const Step& step) const {
  double sum = 0.0;
  for (std::size_t a = 0; a < pose_H_.size(); ++a) {
    const Vector6 dx = step.poses.segment<6>(6 * static_cast<Eigen::Index>(a));
    sum += pose_g_[a].dot(dx) + 0.5 * dx.dot(pose_H_[a] * dx);
  }
  sum += landmarkModel(points_, step.poses, step.points) + landmarkModel(lines_, step.poses, step.lines);
  return -sum;
}

double SchurSystem::maxGradient() const {
  double m = std::max(maxLandmarkGradient(points_), maxLandmarkGradient(lines_));
  for (const Vector6& g : pose_g_) m = std::max(m, g.cwiseAbs().maxCoeff());
  return m;
}

}  // namespace lvslam::visual
