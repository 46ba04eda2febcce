#include "lvslam/sim/robot_trajectory.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "lvslam/core/error.h"
#include "lvslam/core/se3.h"
#include "lvslam/sim/counter_random.h"

namespace lvslam::sim {

namespace {
constexpr int kSamplesPerSegment = 400;
constexpr double kTwoPi = 6.283185307179586;
constexpr std::array<double, 3> kShakeHz{1.7, 3.1, 5.3};
constexpr std::array<double, 3> kShakeWeight{0.5, 0.3, 0.2};
}  // namespace

RobotTrajectory::RobotTrajectory(const PathConfig& config, std::uint64_t seed) : config_(config) {
  if (config_.waypoints.size() < 3) throw Error("sim::PathConfig", "a closed path needs at least 3 waypoints");
  if (!(config_.max_speed > 0.0) || !(config_.acceleration > 0.0) || !(config_.max_turn_rate > 0.0))
    throw Error("sim::PathConfig", "speed, acceleration and turn rate must be positive");
  CounterRandom rng(seed, RandomStream::kTrajectory, 0);
  for (double& phase : shake_phase_) phase = rng.uniform(0.0, kTwoPi);
  buildSpline();
  buildTimeTable();
}

// Periodic natural cubic spline with unit knot spacing: M_{i-1} + 4 M_i +
// M_{i+1} = 6 (P_{i+1} - 2 P_i + P_{i-1}) (de Boor, A Practical Guide to Splines).
void RobotTrajectory::buildSpline() {
  const int n = static_cast<int>(config_.waypoints.size());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  Eigen::MatrixXd b(n, 2);
  for (int i = 0; i < n; ++i) {
    const int prev = (i + n - 1) % n, next = (i + 1) % n;
    A(i, prev) += 1.0;
    A(i, i) += 4.0;
    A(i, next) += 1.0;
    b.row(i) = 6.0 * (config_.waypoints[next] - 2.0 * config_.waypoints[i] + config_.waypoints[prev]).transpose();
  }
  const Eigen::MatrixXd M = A.partialPivLu().solve(b);
  second_derivatives_.resize(n);
  for (int i = 0; i < n; ++i) second_derivatives_[i] = M.row(i).transpose();
}

Eigen::Vector2d RobotTrajectory::position(double u) const { return derivative(u, 0); }

Eigen::Vector2d RobotTrajectory::derivative(double u, int order) const {
  const int n = static_cast<int>(config_.waypoints.size());
  const double wrapped = u - n * std::floor(u / n);
  const int i = std::min(static_cast<int>(wrapped), n - 1);
  const double s = wrapped - i, r = 1.0 - s;
  const Eigen::Vector2d& P0 = config_.waypoints[i];
  const Eigen::Vector2d& P1 = config_.waypoints[(i + 1) % n];
  const Eigen::Vector2d& M0 = second_derivatives_[i];
  const Eigen::Vector2d& M1 = second_derivatives_[(i + 1) % n];
  if (order == 0) return r * P0 + s * P1 + ((r * r * r - r) * M0 + (s * s * s - s) * M1) / 6.0;
  if (order == 1) return P1 - P0 + ((1.0 - 3.0 * r * r) * M0 + (3.0 * s * s - 1.0) * M1) / 6.0;
  return r * M0 + s * M1;
}

// Speed profile: the turn-rate limit v <= w_max / curvature, then forward and
// backward passes bounding the acceleration (v^2 <= v_prev^2 + 2 a ds), from rest.
void RobotTrajectory::buildTimeTable() {
  const int n = static_cast<int>(config_.waypoints.size());
  const double du = 1.0 / kSamplesPerSegment;
  double loop_length = 0.0;
  for (int k = 0; k < n * kSamplesPerSegment; ++k) loop_length += (position((k + 1) * du) - position(k * du)).norm();
  const int loops = static_cast<int>(std::ceil((config_.duration + 2.0) * config_.max_speed / loop_length)) + 1;
  const int count = loops * n * kSamplesPerSegment + 1;
  std::vector<double> s(count, 0.0), v(count);
  for (int k = 0; k < count; ++k) {
    const double u = k * du;
    if (k > 0) s[k] = s[k - 1] + (position(u) - position(u - du)).norm();
    const Eigen::Vector2d d1 = derivative(u, 1), d2 = derivative(u, 2);
    const double curvature = std::abs(d1.x() * d2.y() - d1.y() * d2.x()) / std::pow(d1.norm(), 3);
    v[k] = std::min(config_.max_speed, config_.max_turn_rate / std::max(curvature, 1e-9));
  }
  v[0] = 0.0;
  const double a2 = 2.0 * config_.acceleration;
  for (int k = 1; k < count; ++k) v[k] = std::min(v[k], std::sqrt(v[k - 1] * v[k - 1] + a2 * (s[k] - s[k - 1])));
  for (int k = count - 2; k > 0; --k) v[k] = std::min(v[k], std::sqrt(v[k + 1] * v[k + 1] + a2 * (s[k + 1] - s[k])));
  table_.resize(count);
  table_[0] = {0.0, 0.0, 0.0};
  for (int k = 1; k < count; ++k) {
    const double dt = (s[k] - s[k - 1]) / std::max(0.5 * (v[k] + v[k - 1]), 1e-3);
    table_[k] = {table_[k - 1].t + dt, k * du, v[k]};
  }
}

RobotTrajectory::Sample RobotTrajectory::sampleAt(double t) const {
  const double tc = std::clamp(t, 0.0, table_.back().t);
  const auto it = std::upper_bound(table_.begin(), table_.end(), tc, [](double x, const Sample& s) { return x < s.t; });
  if (it == table_.end()) return table_.back();
  const Sample& b = *it;
  const Sample& a = *(it - 1);
  const double w = (tc - a.t) / (b.t - a.t);
  return {tc, a.u + w * (b.u - a.u), a.v + w * (b.v - a.v)};
}

double RobotTrajectory::speedAt(double t) const { return sampleAt(t).v; }

Eigen::Isometry3d RobotTrajectory::T_world_body(double t) const {
  const Sample sample = sampleAt(t);
  const Eigen::Vector2d xy = position(sample.u);
  const Eigen::Vector2d heading = derivative(sample.u, 1);
  const double yaw = std::atan2(heading.y(), heading.x());
  // A platform shakes more the faster it drives.
  const double level = 0.2 + 0.8 * sample.v / config_.max_speed;
  auto shake = [&](int axis) {
    double sum = 0.0;
    for (int k = 0; k < 3; ++k)
      sum += kShakeWeight[k] * std::sin(kTwoPi * kShakeHz[k] * sample.t + shake_phase_[3 * axis + k]);
    return level * sum;
  };
  const double amplitude = config_.shake_deg * M_PI / 180.0;
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(amplitude * shake(1), Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(amplitude * shake(0), Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  return makePose(R, Eigen::Vector3d(xy.x(), xy.y(), config_.shake_height * shake(2)));
}

}  // namespace lvslam::sim
