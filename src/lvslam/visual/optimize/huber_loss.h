#pragma once
// The Huber loss on a whitened residual of squared norm s (Ceres' HuberLoss:
// rho(s) = s inside delta, 2 delta sqrt(s) - delta^2 beyond) and its IRLS
// weight rho'(s), shared by the pose LM and the local BA.
#include <cmath>

namespace lvslam::visual {

inline double huberLoss(double s, double delta) {
  return s <= delta * delta ? s : 2.0 * delta * std::sqrt(s) - delta * delta;
}

inline double huberWeight(double s, double delta) { return s <= delta * delta ? 1.0 : delta / std::sqrt(s); }

}  // namespace lvslam::visual
