#pragma once
// SE3 helpers over Eigen. Poses are Eigen::Isometry3d named T_a_b: they map
// points of frame b into frame a (p_a = T_a_b * p_b). Twists are 6-vectors
// ordered (rho, phi): translational part first, rotational part second.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace lvslam {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

Eigen::Matrix3d skew(const Eigen::Vector3d& v);

// SO3 exponential and logarithm (Rodrigues), stable near zero and near pi.
Eigen::Matrix3d expSO3(const Eigen::Vector3d& phi);
Eigen::Vector3d logSO3(const Eigen::Matrix3d& R);

// Left Jacobian of SO3 and its inverse (Barfoot, State Estimation, 7.1.3).
Eigen::Matrix3d leftJacobianSO3(const Eigen::Vector3d& phi);
Eigen::Matrix3d leftJacobianSO3Inverse(const Eigen::Vector3d& phi);

// SE3 exponential and logarithm: T = [exp(phi), J_l(phi) rho; 0, 1].
Eigen::Isometry3d expSE3(const Vector6d& xi);
Vector6d logSE3(const Eigen::Isometry3d& T);

// True when R is a proper rotation: R^T R = I and det R = 1, within tol.
bool isRotation(const Eigen::Matrix3d& R, double tol = 1e-3);
// True when T is finite and its linear part is a rotation (isRotation).
bool isRigidTransform(const Eigen::Isometry3d& T, double tol = 1e-3);

// Re-orthonormalises a nearly-rotation matrix (closest rotation in Frobenius norm).
Eigen::Matrix3d closestRotation(const Eigen::Matrix3d& M);

Eigen::Isometry3d makePose(const Eigen::Quaterniond& q, const Eigen::Vector3d& t);
Eigen::Isometry3d makePose(const Eigen::Matrix3d& R, const Eigen::Vector3d& t);

// Pose between a and b at fraction s in [0, 1]: slerp of the rotations and
// lerp of the translations (what constant angular and linear velocity over
// the interval gives for a ground robot).
Eigen::Isometry3d interpolate(const Eigen::Isometry3d& T_a, const Eigen::Isometry3d& T_b, double s);

// Pose at time t from poses at t0 and t1 (extrapolates linearly outside).
Eigen::Isometry3d interpolateAtTime(double t, double t0, const Eigen::Isometry3d& T0, double t1,
                                    const Eigen::Isometry3d& T1);

// exp(delta) T, the rotation re-normalised so that repeated updates stay on
// SE(3) (the left update of the visual optimisers and the pose fusion).
Eigen::Isometry3d leftUpdate(const Vector6d& delta, const Eigen::Isometry3d& T);

// Rotation angle of a pose in radians, in [0, pi].
double rotationAngle(const Eigen::Isometry3d& T);

// T_from moved toward T_to along the geodesic T_from * exp(s log(T_from^-1 T_to)),
// s in [0, 1] as large as keeps the step within max_m and max_rad.
Eigen::Isometry3d boundedStep(const Eigen::Isometry3d& T_from, const Eigen::Isometry3d& T_to, double max_m,
                              double max_rad);

}  // namespace lvslam
